#pragma once
// VTK XML files written and read without VTK's own terminal output: its error blocks are
// silenced (QuietVtk) and a failed write is reported as one error naming the file and the
// reason in words (a full disk as ENOSPC).
#include <string>

class vtkXMLWriter;

namespace flexehd::cosim {

/// Silences VTK's own error and warning printing for a scope.
class QuietVtk {
public:
    QuietVtk();
    ~QuietVtk();
    QuietVtk(const QuietVtk&) = delete;
    QuietVtk& operator=(const QuietVtk&) = delete;

private:
    int was_;
};

/// Writes `writer`'s input to `path` atomically (fem::writeAtomically). Throws
/// std::runtime_error "cannot write 'path': reason" when VTK fails.
void writeVtkXmlAtomically(const std::string& path, vtkXMLWriter& writer);

}  // namespace flexehd::cosim
