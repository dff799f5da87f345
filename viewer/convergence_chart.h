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

 private:
  vtkSmartPointer<vtkRenderer> renderer_;
  vtkSmartPointer<vtkChartXY> chart_;
  vtkSmartPointer<vtkContextActor> actor_;
  vtkSmartPointer<vtkTable> table_;
};

}  // namespace rad
