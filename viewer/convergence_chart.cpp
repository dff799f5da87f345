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
#include <vtkTextRenderer.h>

#include <cmath>
#include <sstream>

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
  chart_->GetTitleProperties()->SetJustificationToCentered();
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
  measure_ = measure;
  if (panelWidth_ > 0)
    fitTitle(panelWidth_, dpi_);
  else
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

bool ConvergenceChart::fitTitle(int panelWidthPixels, int dpi) {
  panelWidth_ = panelWidthPixels, dpi_ = dpi;
  // vtkChartXY centres the title on the plot area, which starts after the left axis (its labels
  // and title, up to about leftBorder pixels) and ends rightBorder pixels before the panel's edge:
  // the title stays inside the panel while it is no wider than twice the room right of the centre.
  constexpr int leftBorder = 80, rightBorder = 20, margin = 4;
  const double room = panelWidthPixels - leftBorder + rightBorder - 2 * margin;
  std::vector<std::string> words{"convergence:"};
  std::istringstream in(measure_);
  for (std::string w; in >> w;) words.push_back(w);
  vtkTextProperty* style = chart_->GetTitleProperties();
  vtkTextRenderer* text = vtkTextRenderer::GetInstance();
  auto width = [&](const std::string& s) {
    int box[4] = {0, 0, 0, 0};
    if (!text || !text->GetBoundingBox(style, s, box, dpi)) return 8.0 * s.size();  // no FreeType
    return static_cast<double>(box[1] - box[0] + 1);
  };
  for (int size = 13; size >= 9; --size) {
    style->SetFontSize(size);
    // Greedy wrap between words, at most three lines.
    std::vector<std::string> lines;
    bool fits = true;
    for (const std::string& w : words) {
      if (!lines.empty() && width(lines.back() + " " + w) <= room)
        lines.back() += " " + w;
      else
        lines.push_back(w);
      fits = fits && width(lines.back()) <= room;
    }
    if (fits && lines.size() <= 3) {
      std::string title = lines[0];
      for (size_t k = 1; k < lines.size(); ++k) title += "\n" + lines[k];
      chart_->SetTitle(title);
      return true;
    }
  }
  chart_->SetTitle("");
  return false;
}

}  // namespace rad
