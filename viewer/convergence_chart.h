#pragma once

#include <vtkRenderer.h>
#include <vtkSmartPointer.h>

#include <string>
#include <vector>

class vtkChartXY;
class vtkContextActor;
class vtkTable;

namespace rad {

// The convergence curve (the solver's measure per iteration, log scale) drawn with VTK's charts
// in a renderer of its own, so it can share a window with the 3D view.
class ConvergenceChart {
 public:
  ConvergenceChart();
  vtkRenderer* renderer() const { return renderer_; }
  // history[k]: the measure after k iterations; values <= 0 cannot be drawn on a log scale.
  void setHistory(const std::vector<double>& history, const std::string& measure, double tolerance);
  // Sets the title for a panel this many pixels wide: "convergence: MEASURE" on one line when it
  // fits, else wrapped between words, at 13 px down to 9 px. False when even that does not fit
  // (the caller hides the panel rather than show a cut title).
  bool fitTitle(int panelWidthPixels, int dpi);

 private:
  vtkSmartPointer<vtkRenderer> renderer_;
  vtkSmartPointer<vtkChartXY> chart_;
  vtkSmartPointer<vtkContextActor> actor_;
  vtkSmartPointer<vtkTable> table_;
  std::string measure_;
  int panelWidth_ = 0, dpi_ = 72;
};

}  // namespace rad
