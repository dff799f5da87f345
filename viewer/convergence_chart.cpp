#include "viewer/convergence_chart.h"

#include <vtkAxis.h>
#include <vtkChartXY.h>
#include <vtkContextActor.h>
#include <vtkContextScene.h>
#include <vtkDoubleArray.h>
#include <vtkPen.h>
#include <vtkPlot.h>
#include <vtkTable.h>
#include <vtkTextProperty.h>

#include <cmath>

namespace rad {

ConvergenceChart::ConvergenceChart()
    : renderer_(vtkSmartPointer<vtkRenderer>::New()),
      chart_(vtkSmartPointer<vtkChartXY>::New()),
      actor_(vtkSmartPointer<vtkContextActor>::New()),
      table_(vtkSmartPointer<vtkTable>::New()) {
  renderer_->SetBackground(1, 1, 1);
  actor_->GetScene()->AddItem(chart_);
  renderer_->AddActor(actor_);
  actor_->GetScene()->SetRenderer(renderer_);
  chart_->SetShowLegend(false);
  chart_->GetAxis(vtkAxis::BOTTOM)->SetTitle("iteration");
  chart_->GetAxis(vtkAxis::LEFT)->SetLogScale(true);
  chart_->GetTitleProperties()->SetFontSize(13);
  for (const char* name : {"iteration", "measure", "tolerance"}) {
    auto column = vtkSmartPointer<vtkDoubleArray>::New();
    column->SetName(name);
    table_->AddColumn(column);
  }
}

void ConvergenceChart::setHistory(const std::vector<double>& history, const std::string& measure,
                                  double tolerance) {
  table_->SetNumberOfRows(0);
  for (size_t k = 0; k < history.size(); ++k) {
    if (!(history[k] > 0) || !std::isfinite(history[k])) continue;  // log scale
    const vtkIdType row = table_->InsertNextBlankRow();
    table_->SetValue(row, 0, static_cast<double>(k));
    table_->SetValue(row, 1, history[k]);
    table_->SetValue(row, 2, tolerance > 0 ? tolerance : history[k]);
  }
  table_->Modified();
  chart_->ClearPlots();
  chart_->SetTitle("convergence: " + measure);
  chart_->GetAxis(vtkAxis::LEFT)->SetTitle(measure.size() > 24 ? "measure (log)" : measure);
  if (table_->GetNumberOfRows() < 1) return;
  vtkPlot* curve = chart_->AddPlot(vtkChart::LINE);
  curve->SetInputData(table_, 0, 1);
  curve->SetColor(31, 119, 180, 255);
  curve->SetWidth(2.0);
  if (tolerance > 0) {
    vtkPlot* line = chart_->AddPlot(vtkChart::LINE);
    line->SetInputData(table_, 0, 2);
    line->SetColor(200, 60, 60, 255);
    line->GetPen()->SetLineType(vtkPen::DASH_LINE);
  }
  chart_->RecalculateBounds();
}

}  // namespace rad
