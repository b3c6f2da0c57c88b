#include "cosim/io/VtkXmlFile.hpp"

#include <cerrno>
#include <stdexcept>

#include <vtkErrorCode.h>
#include <vtkObject.h>
#include <vtkXMLWriter.h>

#include "fem/AtomicFile.hpp"

namespace flexehd::cosim {

QuietVtk::QuietVtk() : was_(vtkObject::GetGlobalWarningDisplay()) { vtkObject::GlobalWarningDisplayOff(); }
QuietVtk::~QuietVtk() { vtkObject::SetGlobalWarningDisplay(was_); }

void writeVtkXmlAtomically(const std::string& path, vtkXMLWriter& writer) {
    fem::writeAtomically(path, [&](const std::string& tmp) {
        const QuietVtk quiet;
        writer.SetFileName(tmp.c_str());
        errno = 0;
        const int ok = writer.Write();
        const int err = errno;
        const unsigned long code = writer.GetErrorCode();
        if (ok == 1 && code == vtkErrorCode::NoError) return;
        const int reason = code == vtkErrorCode::OutOfDiskSpaceError ? ENOSPC : err;
        throw std::runtime_error("cannot write '" + path + "': " + fem::writeFailureReason(tmp, reason));
    });
}

}  // namespace flexehd::cosim
