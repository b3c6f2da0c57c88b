// Benchmark of the grid/structure mappings: load mapping (cosim/mapping/LoadMapping: common refinement
// and sparse assembly, once) and deformation mapping (cosim/mapping/DeformationMapping: Clough–Tocher
// rows, once); setup and one application (per coupling call) timed separately, as coupling
// libraries do; the modal pre-multiplied operators (cosim/mapping/ModalMapping: modes × grid,
// grid × modes) with real Craig–Bampton shapes; and the liner with the moving grid
// (cosim/mapping/MovingGridMapping) against rebuilding both operators at each piston position, with
// the shear tractions (friction on the liner) through the same projection.
//   bench_mapping [MESH_SIZE_M] [N_AXIAL] [N_THETA] [MODES] [LINER_SIZE_M] [FIXED_ROWS]
// Defaults: piston.geo at 0.004 m, a 100 × 200 = 20 000-node full-circumference skirt grid,
// 30 fixed-interface modes (pin bore RBE2, no static correction); liner.geo at 0.005 m with a
// bore-fixed grid of 321 rows (h = 0.5 mm) × the skirt grid's 200 columns.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "cosim/mapping/DeformationMapping.hpp"
#include "cosim/mapping/LoadMapping.hpp"
#include "cosim/mapping/ModalMapping.hpp"
#include "cosim/mapping/MovingGridMapping.hpp"
#include "fem/MeshReader.hpp"
#include "modal/CraigBamptonReducer.hpp"

using namespace flexehd;
using Clock = std::chrono::steady_clock;

static double seconds(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// Median time of `reps` calls of f, in seconds.
template <typename F>
static double median(int reps, F f) {
    std::vector<double> t;
    for (int r = 0; r < reps; ++r) {
        const auto t0 = Clock::now();
        f();
        t.push_back(seconds(t0));
    }
    std::nth_element(t.begin(), t.begin() + reps / 2, t.end());
    return t[static_cast<std::size_t>(reps / 2)];
}

int main(int argc, char** argv) {
    const double size = argc > 1 ? std::stod(argv[1]) : 0.004;
    const int nz = argc > 2 ? std::stoi(argv[2]) : 100;
    const int nt = argc > 3 ? std::stoi(argv[3]) : 200;
    const int modes = argc > 4 ? std::stoi(argv[4]) : 30;
    const double linerSize = argc > 5 ? std::stod(argv[5]) : 0.005;
    const int fixedRows = argc > 6 ? std::stoi(argv[6]) : 321;

    auto t0 = Clock::now();
    const fem::Mesh mesh = fem::readMesh(std::string(FLEXEHD_SOURCE_DIR) + "/meshes/piston.geo", {2, size});
    std::printf("mesh: piston.geo size %.4f m, %d nodes, %d surface triangles (%.2f s)\n", size,
                mesh.numNodes(), static_cast<int>(mesh.surface.size()), seconds(t0));

    const auto grid = lube::FilmGrid::fullCircumference(0.043, lube::FilmGrid::uniform(-0.0249, 0.0107, nz), nt);
    double setup = 1e300;
    cosim::LoadMapping* keep = nullptr;
    for (int r = 0; r < 3; ++r) {  // best of 3
        t0 = Clock::now();
        auto* m = new cosim::LoadMapping(mesh, "skirt", grid);
        setup = std::min(setup, seconds(t0));
        delete keep;
        keep = m;
    }
    const cosim::LoadMapping& map = *keep;
    const auto& s = map.stats();
    std::printf("grid: %d x %d = %d nodes; operator %ld x %ld, %ld nonzeros; %d fragments, rule %d x %d\n",
                nz, nt, grid.size(), static_cast<long>(map.matrix().rows()),
                static_cast<long>(map.matrix().cols()), static_cast<long>(map.matrix().nonZeros()),
                s.fragments, s.quadratureOrder, s.quadratureOrder);
    std::printf("coverage %.4f, faceting error %.2e, mid-node offset %.1e m\n", s.coveredArea / s.gridArea,
                s.facetingError, s.midNodeOffset);
    std::printf("setup (best of 3): %.3f s\n", setup);

    const Eigen::VectorXd p = Eigen::VectorXd::Random(grid.size()).array() + 1.0;
    Eigen::VectorXd f(map.matrix().rows());
    const double call = median(1001, [&] { map.apply(p, f); });
    std::printf("apply (nodal forces, median of 1001): %.1f us\n", call * 1e6);

    t0 = Clock::now();
    const cosim::DeformationMapping def(mesh, "skirt", grid);
    const double defSetup = seconds(t0);
    std::printf("deformation: %ld x %ld radial operator, %ld nonzeros, %zu grid nodes off the skirt; setup %.3f s\n",
                static_cast<long>(def.radial().rows()), static_cast<long>(def.radial().cols()),
                static_cast<long>(def.radial().nonZeros()), def.outsideNodes().size(), defSetup);
    const Eigen::VectorXd u = Eigen::VectorXd::Random(def.radial().cols()) * 1e-5;
    Eigen::VectorXd ur(grid.size());
    const double defCall = median(1001, [&] { ur.noalias() = def.radial() * u; });
    std::printf("apply u_r = D u (median of 1001): %.1f us\n", defCall * 1e6);
    t0 = Clock::now();
    const cosim::LoadMapping withShear(mesh, "skirt", grid, {0.0, 1e-3, true});
    std::printf("load setup with the shear operators: %.3f s\n", seconds(t0));
    Eigen::VectorXd fs;
    const double shearCall = median(1001, [&] { fs = withShear.applyShear(p, p); });
    std::printf("apply shear (tau_z and tau_theta, median of 1001): %.1f us\n", shearCall * 1e6);

    // Modal operators with real mode shapes (Craig–Bampton, pin bore RBE2).
    modal::ReductionSettings rs;
    rs.normalModes = modes;
    t0 = Clock::now();
    const modal::ReducedBody body =
        modal::CraigBamptonReducer(mesh, {7.5e10, 0.33, 2700.0}).reduce({modal::parseInterface("pin_bore:rbe2")}, rs);
    std::printf("Craig-Bampton reduction (%d modes incl. 6 rigid): %.2f s\n", body.numModes(), seconds(t0));
    t0 = Clock::now();
    const cosim::ModalMapping mm(body, map, def);
    std::printf("modal operators %d x %d and %d x %d: pre-multiply %.3f s\n", body.numModes(), grid.size(),
                grid.size(), body.numModes(), seconds(t0));
    Eigen::VectorXd g(body.numModes());
    const double modal = median(1001, [&] { mm.modalForce(p, g); });
    const Eigen::VectorXd q = Eigen::VectorXd::Random(body.numModes()) * 1e-4;
    const double modalD = median(1001, [&] { mm.radialDisplacement(q, ur); });
    std::printf("apply modal force B p: %.1f us; grid deformation G q: %.1f us\n", modal * 1e6, modalD * 1e6);

    // Liner: bore-fixed grid once, then per piston position a projection + window product.
    t0 = Clock::now();
    const fem::Mesh liner = fem::readMesh(std::string(FLEXEHD_SOURCE_DIR) + "/meshes/liner.geo", {2, linerSize});
    std::printf("liner mesh: size %.4f m, %d nodes (%.2f s)\n", linerSize, liner.numNodes(), seconds(t0));
    t0 = Clock::now();
    cosim::MovingGridMapping moving(liner, "bore", grid, -0.16, 0.0, fixedRows);
    std::printf("moving-grid setup: fixed grid %d x %d, load %ld nonzeros, deformation %ld nonzeros: %.3f s\n",
                moving.fixedGrid().nAxial(), moving.fixedGrid().nTheta(),
                static_cast<long>(moving.fixedLoad().matrix().nonZeros()),
                static_cast<long>(moving.fixedDeformation().radial().nonZeros()), seconds(t0));
    Eigen::VectorXd fl(3 * liner.numNodes()), ul = Eigen::VectorXd::Random(3 * liner.numNodes()) * 1e-5, url;
    int position = 0;
    auto offset = [&] {  // golden-ratio sequence over [-0.12, -0.02] m: never on a fixed row
        const double x = 0.6180339887 * ++position;
        return -0.12 + 0.1 * (x - std::floor(x));
    };
    const double linerLoad = median(301, [&] { moving.loads(p, offset(), fl); });
    const double linerDef = median(301, [&] { moving.radialDisplacement(ul, offset(), url); });
    std::printf("per position (median of 301, varying offsets): loads %.1f us, radial displacement %.1f us\n",
                linerLoad * 1e6, linerDef * 1e6);
    const double rebuild = median(3, [&] {
        const double s0 = offset();
        const cosim::LoadMapping a(liner, "bore", grid, {s0, 1e-3});
        const cosim::DeformationMapping d(liner, "bore", grid, s0);
        fl = a.apply(p);
    });
    std::printf("rebuilding both operators per position instead (median of 3): %.3f s\n", rebuild);
    // Modal liner: the cost only depends on the mode count (random stand-in for the liner's Φ).
    t0 = Clock::now();
    moving.setModes(Eigen::MatrixXd::Random(3 * liner.numNodes(), body.numModes()));
    std::printf("moving grid, modal (%d modes): pre-multiply %.3f s\n", body.numModes(), seconds(t0));
    Eigen::VectorXd gl, urm;
    const double linerModalLoad = median(301, [&] { gl = moving.modalForce(p, offset()); });
    const double linerModalDef = median(301, [&] { urm = moving.modalRadialDisplacement(q, offset()); });
    std::printf("per position, modal: forces %.1f us, radial displacement %.1f us\n", linerModalLoad * 1e6,
                linerModalDef * 1e6);
    // Liner friction: the same moving grid with G's shear operators (τ_z, τ_θ).
    t0 = Clock::now();
    cosim::MovingGridMapping movingShear(liner, "bore", grid, -0.16, 0.0, fixedRows, cosim::MovingGridOptions{1e-3, true});
    std::printf("moving-grid setup with the shear operators: %.3f s\n", seconds(t0));
    Eigen::VectorXd fsl;
    const double linerShear = median(301, [&] { movingShear.shearLoads(p, p, offset(), fsl); });
    t0 = Clock::now();
    movingShear.setModes(Eigen::MatrixXd::Random(3 * liner.numNodes(), body.numModes()));
    std::printf("per position: shear loads (tau_z and tau_theta) %.1f us; modal pre-multiplication with shear %.3f s\n",
                linerShear * 1e6, seconds(t0));
    Eigen::VectorXd gsl;
    const double linerModalShear = median(301, [&] { gsl = movingShear.modalShearForce(p, p, offset()); });
    std::printf("per position, modal shear forces (tau_z and tau_theta): %.1f us\n", linerModalShear * 1e6);
    delete keep;
    return f.sum() + g.sum() + ur.sum() + fs.sum() + fl.sum() + url.sum() + gl.sum() + urm.sum() + fsl.sum() +
                       gsl.sum() > 1e300
               ? 1
               : 0;  // keep the results alive
}
