#include "cosim/io/PvdWriter.hpp"

#include <sstream>
#include <iomanip>
#include <stdexcept>

#include "fem/AtomicFile.hpp"

namespace flexehd::cosim {

void PvdCollection::write(const std::string& path) const {
    std::ostringstream out;
    out << "<?xml version=\"1.0\"?>\n"
           "<VTKFile type=\"Collection\" version=\"1.0\" byte_order=\"LittleEndian\">\n"
           "  <Collection>\n"
        << std::setprecision(17);
    for (const auto& e : entries_)
        out << "    <DataSet timestep=\"" << e.time << "\" group=\"\" part=\"0\" file=\"" << e.file << "\"/>\n";
    out << "  </Collection>\n</VTKFile>\n";
    fem::writeTextAtomically(path, out.str());
}

}  // namespace flexehd::cosim
