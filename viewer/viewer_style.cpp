#include "viewer/viewer_style.h"

#include <vtkObjectFactory.h>
#include <vtkRenderWindowInteractor.h>

#include "viewer/solution_viewer.h"

namespace rad {

vtkStandardNewMacro(ViewerStyle);

void ViewerStyle::OnChar() {
  vtkRenderWindowInteractor* rwi = this->Interactor;
  const char code = rwi->GetKeyCode();
  const std::string key = code == ' ' ? "space" : std::string(1, code);
  if (viewer_ && viewer_->handleKey(key, rwi->GetEventPosition()[0], rwi->GetEventPosition()[1])) {
    rwi->Render();
    return;
  }
  if (code == 'q' || code == 'Q') vtkInteractorStyleTrackballCamera::OnChar();  // quit
}

void ViewerStyle::OnTimer() {
  if (viewer_ && viewer_->running()) {
    viewer_->runTick();
    this->Interactor->Render();
    return;
  }
  vtkInteractorStyleTrackballCamera::OnTimer();
}

}  // namespace rad
