// Shared by the VTK-based readers (vtk_io, exodus_reader, surface_reader): VTK's messages
// captured as one InputError line, and VTK unstructured grids turned into cell meshes.
#pragma once
#include <map>
#include <mutex>
#include <string>

#include <vtkCallbackCommand.h>
#include <vtkLogger.h>
#include <vtkNew.h>
#include <vtkOutputWindow.h>
#include <vtkSmartPointer.h>

#include "harness/scene/cell_mesh.h"
#include "harness/scene/input_error.h"

class vtkDataArray;
class vtkDataSetAttributes;
class vtkUnstructuredGrid;

namespace vob {

// VTK reports problems through the global output window (and, when an algorithm has an
// observer, as ErrorEvent on it). While a file is read or written, a capturing window
// collects them instead of printing, and the first error becomes one InputError line.
class CaptureWindow : public vtkOutputWindow {
 public:
  static CaptureWindow* New();
  vtkTypeMacro(CaptureWindow, vtkOutputWindow);
  void DisplayText(const char* t) override { keep(t); }
  void DisplayErrorText(const char* t) override { keep(t); }
  // A warning on reading is a problem with the file too (VTK reports a short binary read
  // as one), so it is kept like an error.
  void DisplayWarningText(const char* t) override { keep(t); }
  void DisplayGenericWarningText(const char* t) override { keep(t); }
  void DisplayDebugText(const char*) override {}
  // VTK messages read "ERROR: In file, line N\nClass (0x...): text" (or "Warning: In ..."):
  // keep the text.
  void keep(const char* t) {
    if (!first.empty() || !t) return;
    std::string msg = t;
    std::string best;
    size_t start = 0;
    while (start <= msg.size()) {
      size_t end = msg.find('\n', start);
      if (end == std::string::npos) end = msg.size();
      std::string line = msg.substr(start, end - start);
      start = end + 1;
      if (line.empty() || line.rfind("ERROR: In ", 0) == 0 || line.rfind("Warning: In ", 0) == 0 ||
          line.rfind("Generic Warning: In ", 0) == 0)
        continue;
      if (const auto p = line.find("): "); p != std::string::npos && line.find(" (0x") < p)
        line = line.substr(p + 3);
      best = line;
      break;
    }
    first = best.empty() ? msg : best;
  }
  std::string first;
};

// The output window and the logger level are process-wide: one capture at a time.
extern std::mutex capture_mutex;

class ScopedCapture {
 public:
  // VTK also logs errors to stderr through vtkLogger; that is muted meanwhile. vtkLogger
  // has no getter for the stderr level: the cutoff equals it unless log callbacks exist.
  ScopedCapture()
      : lock_(capture_mutex),
        prev_(vtkOutputWindow::GetInstance()),
        level_(vtkLogger::GetCurrentVerbosityCutoff()) {
    vtkOutputWindow::SetInstance(win_);
    vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  }
  ~ScopedCapture() {
    if (algo_) {  // the window dies with us; so must the links
      algo_->RemoveObserver(tag_);
      algo_->RemoveObserver(warning_tag_);
    }
    vtkLogger::SetStderrVerbosity(level_);
    vtkOutputWindow::SetInstance(prev_);
  }
  void forward(vtkObject* algo) {
    cb_->SetCallback([](vtkObject*, unsigned long, void* self, void* data) {
      static_cast<CaptureWindow*>(self)->keep(static_cast<const char*>(data));
    });
    cb_->SetClientData(win_.Get());
    algo_ = algo;
    tag_ = algo->AddObserver(vtkCommand::ErrorEvent, cb_);
    warning_tag_ = algo->AddObserver(vtkCommand::WarningEvent, cb_);
  }
  const std::string& first() const { return win_->first; }

 private:
  std::lock_guard<std::mutex> lock_;
  vtkSmartPointer<vtkOutputWindow> prev_;
  vtkLogger::Verbosity level_;
  vtkNew<CaptureWindow> win_;
  vtkNew<vtkCallbackCommand> cb_;
  vtkObject* algo_ = nullptr;
  unsigned long tag_ = 0, warning_tag_ = 0;
};

template <class Algo>
void run_checked(Algo* algo, const std::string& path, const char* what) {
  ScopedCapture capture;
  capture.forward(algo);
  algo->Update();
  if (!capture.first().empty()) throw InputError(path, what, "VTK: " + capture.first());
}


// The active scalars, else the first array; nullptr when there is none.
vtkDataArray* pick_array(vtkDataSetAttributes* a);

// The volume cells of `ug`. Vertices, lines and surface cells beside them (gmsh writes its
// boundary and edge elements into the same file) are skipped and counted in `skipped` by
// class name; a volume cell other than the four linear types is refused. Points are kept
// as numbered in the file, so point data stays aligned with them. Point scalars from
// `scalars` when given, else (with `pick`) pick_array of the point data. With
// `allow_empty`, a grid without volume cells gives an empty mesh instead of an error.
CellMesh cells_from_unstructured(vtkUnstructuredGrid* ug, const std::string& path,
                                 std::map<std::string, size_t>& skipped, vtkDataArray* scalars = nullptr,
                                 bool pick = true, bool allow_empty = false);

// "read the volume cells only; skipped 40 cells of lower dimension (vtkLine 12, ...)", or "".
std::string skipped_note(const std::map<std::string, size_t>& skipped);

}  // namespace vob
