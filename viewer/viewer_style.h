#pragma once

#include <vtkInteractorStyleTrackballCamera.h>

namespace rad {

class SolutionViewer;

// Trackball camera that hands keys and timer ticks to the viewer. VTK's default keys (w
// wireframe, s surface, e exit, p pick, ...) are replaced by the viewer's; q still quits.
class ViewerStyle : public vtkInteractorStyleTrackballCamera {
 public:
  static ViewerStyle* New();
  vtkTypeMacro(ViewerStyle, vtkInteractorStyleTrackballCamera);

  void setViewer(SolutionViewer* viewer) { viewer_ = viewer; }
  void OnChar() override;
  void OnTimer() override;

 private:
  SolutionViewer* viewer_ = nullptr;
};

}  // namespace rad
