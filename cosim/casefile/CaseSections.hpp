#pragma once
// The readers of the case file's sections (docs/case-file.md, "Keys"), one file each: every
// reader takes the top-level mapping, checks its section's keys and fills its part of the
// case. Those whose section the cross-section checks (CrossSectionChecks.hpp) name return it.
#include "cosim/case/EngineCase.hpp"
#include "cosim/casefile/CaseFile.hpp"
#include "cosim/casefile/CaseValues.hpp"
#include "cosim/io/YamlSection.hpp"

namespace flexehd::cosim::casefile {

/// engine (required).
YamlSection readEngine(const YamlSection& top, EngineSpec& e);
/// piston (required), checked against the bore.
void readPiston(const YamlSection& top, const EngineSpec& engine, PistonSpec& p);
/// lubricant with its supply; the cavitation pressure checked against the crankcase pressure.
YamlSection readLubricant(const YamlSection& top, const EngineSpec& engine, LubricantSpec& l);
/// contact.
void readContact(const YamlSection& top, ContactSpec& c);
/// rings: the ring pack, top ring first (none when absent), in the case file or in the YAML file it
/// names; each groove placed on the ring belt (after engine, piston and contact: the roughness
/// defaults to contact.sigma).
void readRings(const YamlSection& top, const YamlSection& engine, EngineCase& c);
/// ring_gas: the gas between the rings (after readRings).
void readRingGas(const YamlSection& top, EngineCase& c);
/// cylinder_pressure (required): the table's path, and the table read and checked.
void readCylinderPressure(const YamlSection& top, EngineCase& c);
/// bodies: the piston's and the liner's model and the response (both rigid with
/// options.rigidBodies); sets c.pistonBody, c.linerBody and c.coupling.response.
void readBodies(const YamlSection& top, const CaseFileOptions& options, EngineCase& c);
/// liner: the bore distortion, its table read and checked against the bore.
void readLiner(const YamlSection& top, const EngineSpec& engine, LinerSpec& l);
/// thermal: the thermal-displacement file, read and checked with options.checkBodyFiles.
void readThermal(const YamlSection& top, const CaseFileOptions& options, ThermalSpec& t);
/// grid, checked against the skirt's panels.
void readGrid(const YamlSection& top, const PistonSpec& piston, GridSpec& g);
/// time.
void readTime(const YamlSection& top, TimeSpec& t);
/// coupling (not the response, which bodies sets).
YamlSection readCoupling(const YamlSection& top, CouplingSpec& k);
/// output: the directory resolved against the case file's.
void readOutput(const YamlSection& top, OutputSpec& o);
/// acoustics: the liner's recorded surface velocity; needs a flexible liner and the dynamic
/// response, and caps time.max_step_deg at the sampling interval.
void readAcoustics(const YamlSection& top, EngineCase& c);

}  // namespace flexehd::cosim::casefile
