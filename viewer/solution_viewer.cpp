#include "viewer/solution_viewer.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCommand.h>
#include <vtkDoubleArray.h>
#include <vtkHardwareSelector.h>
#include <vtkIdTypeArray.h>
#include <vtkInformation.h>
#include <vtkPNGWriter.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkSelection.h>
#include <vtkSelectionNode.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkUnsignedCharArray.h>
#include <vtkWindowToImageFilter.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>

#include "radiosity/core/atomic_file.h"
#include "radiosity/core/errors.h"
#include "radiosity/core/interrupt.h"
#include "radiosity/core/log.h"
#include "viewer/convergence_chart.h"
#include "viewer/probe_polydata.h"
#include "viewer/solution_polydata.h"
#include "viewer/viewer_style.h"

namespace rad {
namespace {

// Patch outlines: edges used by one cell only (open borders, creases and material changes,
// where the vertices are split) or by two cells of different patches.
vtkSmartPointer<vtkPolyData> patchOutlines(vtkPolyData* solution) {
  auto* patch = solution->GetCellData()->GetArray(solution_array::patch);
  std::map<std::pair<vtkIdType, vtkIdType>, std::pair<int, int>> edges;  // → (count, patch)
  std::map<std::pair<vtkIdType, vtkIdType>, bool> border;
  vtkIdType n = 0;
  const vtkIdType* ids = nullptr;
  auto* polys = solution->GetPolys();
  polys->InitTraversal();
  for (vtkIdType cell = 0; polys->GetNextCell(n, ids); ++cell) {
    const int p = patch ? static_cast<int>(patch->GetComponent(cell, 0)) : 0;
    for (vtkIdType k = 0; k < n; ++k) {
      const auto key = std::minmax(ids[k], ids[(k + 1) % n]);
      auto [it, added] = edges.try_emplace(key, 1, p);
      if (!added) {
        ++it->second.first;
        if (it->second.second != p) border[key] = true;
      }
    }
  }
  auto lines = vtkSmartPointer<vtkCellArray>::New();
  for (const auto& [key, value] : edges)
    if (value.first == 1 || border.count(key)) {
      const vtkIdType line[2] = {key.first, key.second};
      lines->InsertNextCell(2, line);
    }
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->SetPoints(solution->GetPoints());
  out->SetLines(lines);
  return out;
}

std::string format(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.4g", v);
  return buffer;
}

}  // namespace

SolutionViewer::SolutionViewer(vtkSmartPointer<vtkPolyData> solution, ToneMap toneMap,
                               LiveSolution* live, ViewerOptions options)
    : solution_(std::move(solution)), toneMap_(toneMap), live_(live), options_(std::move(options)) {
  build();
}

SolutionViewer::~SolutionViewer() { delete chart_; }

std::string SolutionViewer::keyHelp() {
  return "h        this help on/off\n"
         "1 ... 9  colour by: 1 tone-mapped colour, 2 radiance, 3/4/5 radiosity red/green/blue,\n"
         "         6 unshot power, 7 element area, 8 refinement level, 9 patch id\n"
         "v        flat elements / smooth vertex colours\n"
         "e        element edges on/off\n"
         "o        patch outlines on/off\n"
         "u        back faces culled / shown\n"
         "p        pick the element under the cursor: print it, draw its form-factor rays\n"
         "         (hierarchical: the links it gathers over)\n"
         "l        draw the rays of the last shot\n"
         "x        clear the rays\n"
         "i        light probes on/off (view DIR with probes.bin, or --probes FILE)\n"
         "space    one solver step (a shot, sweep or bounce)\n"
         "g        run / pause the solver\n"
         "b        restart the solver from B = E\n"
         "a        ambient term on/off (progressive shooting)\n"
         "r        reset the camera\n"
         "q        quit\n"
         "mouse    left: rotate, middle: pan, right or wheel: zoom";
}

void SolutionViewer::build() {
  window_ = vtkSmartPointer<vtkRenderWindow>::New();
  window_->SetSize(options_.width, options_.height);
  window_->SetWindowName(options_.title.c_str());
  window_->SetMultiSamples(0);  // exact colours in screenshots: no blending at edges

  const bool withChart = options_.chart && live_ && !live_->history().empty();
  scene_ = vtkSmartPointer<vtkRenderer>::New();
  scene_->SetBackground(0.32, 0.34, 0.43);
  window_->AddRenderer(scene_);
  // The scalar bar has a strip of its own, in the scene's colour, so it never covers the walls.
  barStrip_ = vtkSmartPointer<vtkRenderer>::New();
  barStrip_->SetBackground(scene_->GetBackground());
  barStrip_->InteractiveOff();
  window_->AddRenderer(barStrip_);

  meshMapper_ = vtkSmartPointer<vtkPolyDataMapper>::New();
  meshMapper_->SetInputData(solution_);
  meshMapper_->SetResolveCoincidentTopologyToPolygonOffset();
  mesh_ = vtkSmartPointer<vtkActor>::New();
  mesh_->SetMapper(meshMapper_);
  // The colours are the surfaces' own outgoing radiance: no shading on top of them.
  mesh_->GetProperty()->LightingOff();
  mesh_->GetProperty()->SetEdgeColor(0.08, 0.08, 0.08);
  scene_->AddActor(mesh_);

  auto outlineMapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  outlineMapper->SetInputData(patchOutlines(solution_));
  outlineMapper->ScalarVisibilityOff();
  outlines_ = vtkSmartPointer<vtkActor>::New();
  outlines_->SetMapper(outlineMapper);
  outlines_->GetProperty()->LightingOff();
  outlines_->GetProperty()->SetColor(1.0, 0.85, 0.2);
  outlines_->GetProperty()->SetLineWidth(2.5);
  scene_->AddActor(outlines_);

  rays_ = vtkSmartPointer<vtkActor>::New();
  rays_->SetMapper(vtkSmartPointer<vtkPolyDataMapper>::New());
  rays_->GetProperty()->LightingOff();
  rays_->GetProperty()->SetOpacity(0.7);
  rays_->VisibilityOff();
  scene_->AddActor(rays_);

  // The probes' colours are their own shading (a white diffuse ball under the probe's light).
  probes_ = vtkSmartPointer<vtkActor>::New();
  probes_->SetMapper(vtkSmartPointer<vtkPolyDataMapper>::New());
  probes_->GetProperty()->LightingOff();
  probes_->VisibilityOff();
  scene_->AddActor(probes_);

  scalarBar_ = vtkSmartPointer<vtkScalarBarActor>::New();
  scalarBar_->SetNumberOfLabels(5);
  scalarBar_->SetLabelFormat("%.3g");
  scalarBar_->SetMaximumWidthInPixels(90);
  scalarBar_->SetBarRatio(0.25);
  scalarBar_->SetVerticalTitleSeparation(6);  // the title clear of the top label
  scalarBar_->GetTitleTextProperty()->SetFontSize(12);
  scalarBar_->GetTitleTextProperty()->ItalicOff();
  scalarBar_->GetLabelTextProperty()->ItalicOff();
  scalarBar_->UnconstrainedFontSizeOn();
  scalarBar_->GetLabelTextProperty()->SetFontSize(12);
  scalarBar_->SetPosition(0.06, 0.06);
  scalarBar_->SetWidth(0.9);
  scalarBar_->SetHeight(0.84);
  barStrip_->AddViewProp(scalarBar_);

  help_ = vtkSmartPointer<vtkTextActor>::New();
  help_->SetInput(keyHelp().c_str());
  help_->GetTextProperty()->SetFontFamilyToCourier();
  help_->GetTextProperty()->SetFontSize(13);
  help_->GetTextProperty()->SetVerticalJustificationToTop();
  help_->GetTextProperty()->SetBackgroundColor(0, 0, 0);
  help_->GetTextProperty()->SetBackgroundOpacity(0.55);
  help_->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  help_->GetPositionCoordinate()->SetValue(0.01, 0.99);
  help_->SetVisibility(options_.help);
  scene_->AddViewProp(help_);

  status_ = vtkSmartPointer<vtkTextActor>::New();
  status_->GetTextProperty()->SetFontSize(13);
  status_->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  status_->GetPositionCoordinate()->SetValue(0.01, 0.01);
  scene_->AddViewProp(status_);

  if (withChart) {
    chart_ = new ConvergenceChart();
    window_->AddRenderer(chart_->renderer());
  }
  layout();
  window_->AddObserver(vtkCommand::StartEvent, this, &SolutionViewer::onRenderStart);

  mesh_->GetProperty()->SetEdgeVisibility(options_.edges);
  outlines_->SetVisibility(options_.outlines);
  mesh_->GetProperty()->SetBackfaceCulling(options_.cullBackFaces);
  resetCamera();
  if (live_ && options_.stopAfter >= 0) {
    live_->restart();
    while (live_->iterations() < options_.stopAfter && !live_->converged()) live_->step();
    refreshSolution();
  }
  refreshColours();
  refreshChart();
  if (options_.pickElement >= 0) showRows(options_.pickElement);
  refreshStatus();
}

ViewerLayout SolutionViewer::layoutFor(int width, int height, bool chart) {
  // The convergence panel takes 36% of the width, and shows only in windows at least 640 px wide
  // and 240 px high (a panel of 230 px or more, with the scene keeping 410 px and more): below
  // that the 3D view gets the room. The scalar bar's strip is 110 px wide, at most a quarter of
  // the window (its fonts shrink with it, from 12 px down to 8), and is dropped below 64 px
  // (windows narrower than 256 px).
  ViewerLayout l;
  l.chart = chart && width >= 640 && height >= 240;
  const double panel = l.chart ? 0.36 : 0.0;
  const double strip = std::min(110.0, 0.25 * width);
  l.barRight = 1 - panel;
  l.sceneRight = strip >= 64 ? l.barRight - strip / width : l.barRight;
  l.barFontSize = std::max(8, std::min(12, static_cast<int>(12 * strip / 110)));
  return l;
}

void SolutionViewer::layout() {
  const int* size = window_->GetSize();
  const int width = size[0] > 0 ? size[0] : options_.width;
  const int height = size[1] > 0 ? size[1] : options_.height;
  if (width == laidOut_[0] && height == laidOut_[1]) return;
  laidOut_[0] = width, laidOut_[1] = height;
  ViewerLayout l = layoutFor(width, height, chart_ != nullptr);
  // A title that cannot fit hides the panel: never a cut title.
  if (l.chart &&
      !chart_->fitTitle(static_cast<int>(std::lround((1 - l.barRight) * width)), window_->GetDPI()))
    l = layoutFor(width, height, false);
  scene_->SetViewport(0, 0, l.sceneRight, 1);
  const bool bar = l.barRight > l.sceneRight;
  barStrip_->SetViewport(bar ? l.sceneRight : 0, 0, bar ? l.barRight : 1, 1);
  barStrip_->SetDraw(bar);
  scalarBar_->GetTitleTextProperty()->SetFontSize(l.barFontSize);
  scalarBar_->GetLabelTextProperty()->SetFontSize(l.barFontSize);
  if (chart_) {
    chart_->renderer()->SetViewport(l.barRight, 0, 1, 1);
    chart_->renderer()->SetDraw(l.chart);
  }
}

void SolutionViewer::resetCamera() {
  double bounds[6];
  solution_->GetBounds(bounds);
  const Eigen::Vector3d lo(bounds[0], bounds[2], bounds[4]), hi(bounds[1], bounds[3], bounds[5]);
  const double* viewport = scene_->GetViewport();
  const int* size = window_->GetSize();
  const double aspect = (viewport[2] - viewport[0]) * (size[0] > 0 ? size[0] : options_.width) /
                        ((viewport[3] - viewport[1]) * (size[1] > 0 ? size[1] : options_.height));
  Camera c;
  if (options_.camera) {
    c = *options_.camera;
  } else {
    // Look along the axis direction d where the most area faces the camera and the least turns
    // away from it (sum A (max(0, -n·d) - max(0, n·d)) = -sum A n·d): a room open on one side is
    // seen through its opening, as a person would frame it. Ties go to +z, the Cornell box
    // convention.
    auto* area = solution_->GetCellData()->GetArray(solution_array::area);
    const Eigen::Vector3d axes[6] = {{0, 0, 1},  {0, 0, -1}, {1, 0, 0},
                                     {-1, 0, 0}, {0, -1, 0}, {0, 1, 0}};
    double facing[6] = {};
    auto* polys = solution_->GetPolys();
    vtkIdType n = 0;
    const vtkIdType* ids = nullptr;
    polys->InitTraversal();
    for (vtkIdType cell = 0; polys->GetNextCell(n, ids); ++cell) {
      double p[3][3];
      for (int k = 0; k < 3; ++k) solution_->GetPoint(ids[k], p[k]);
      const Eigen::Vector3d a(p[0][0], p[0][1], p[0][2]), b(p[1][0], p[1][1], p[1][2]),
          d(p[2][0], p[2][1], p[2][2]);
      const Eigen::Vector3d normal = (b - a).cross(d - a).normalized();
      const double w = area ? area->GetComponent(cell, 0) : 1.0;
      for (int k = 0; k < 6; ++k) facing[k] -= w * normal.dot(axes[k]);
    }
    int best = 0;
    for (int k = 1; k < 6; ++k)
      if (facing[k] > facing[best] + 1e-9 * std::abs(facing[best])) best = k;
    c = frameBounds(lo, hi, axes[best], aspect);
  }
  vtkCamera* camera = scene_->GetActiveCamera();
  applyToView(c, *camera);
  // A view narrower than high (a small window, the bar's strip and the panel taken off) keeps a
  // given camera's whole frame: its angle then spans the width.
  camera->SetUseHorizontalViewAngle(options_.camera && aspect < 1);
  scene_->ResetCameraClippingRange();
}

void SolutionViewer::refreshColours() {
  const DisplayScalar scalar = options_.scalar;
  const bool smooth = options_.smooth && displayScalarInfo(scalar).smoothable;
  const std::vector<double> cells = cellScalars(solution_, scalar);
  if (scalar == DisplayScalar::Colour) {
    meshMapper_->SetColorModeToDirectScalars();
    meshMapper_->SelectColorArray(solution_array::srgb);
  } else {
    auto display = vtkSmartPointer<vtkDoubleArray>::New();
    display->SetName("display");
    const std::vector<double> values = smooth ? pointAverages(solution_, cells) : cells;
    display->SetNumberOfValues(static_cast<vtkIdType>(values.size()));
    for (size_t i = 0; i < values.size(); ++i)
      display->SetValue(static_cast<vtkIdType>(i), values[i]);
    (smooth ? static_cast<vtkDataSetAttributes*>(solution_->GetPointData())
            : static_cast<vtkDataSetAttributes*>(solution_->GetCellData()))
        ->AddArray(display);
    meshMapper_->SetColorModeToMapScalars();
    meshMapper_->SelectColorArray("display");
    meshMapper_->SetInterpolateScalarsBeforeMapping(smooth);
  }
  auto colours = scalarColours(scalar, cells, toneMap_);
  meshMapper_->SetLookupTable(colours);
  meshMapper_->UseLookupTableScalarRangeOn();
  meshMapper_->SetScalarMode(smooth ? VTK_SCALAR_MODE_USE_POINT_FIELD_DATA
                                    : VTK_SCALAR_MODE_USE_CELL_FIELD_DATA);
  meshMapper_->ScalarVisibilityOn();
  meshMapper_->Modified();
  solution_->Modified();
  scalarBar_->SetLookupTable(colours);
  scalarBar_->SetTitle(displayScalarInfo(scalar).title);
  refreshStatus();
}

void SolutionViewer::refreshSolution() {
  if (!live_) return;
  setSolutionArrays(solution_, live_->radiosity(ambient_), live_->unshot(), toneMap_);
  refreshColours();
  refreshChart();
}

void SolutionViewer::refreshChart() {
  if (chart_ && live_) chart_->setHistory(live_->history(), live_->measure(), options_.tolerance);
}

void SolutionViewer::refreshStatus() {
  std::ostringstream s;
  s << displayScalarInfo(options_.scalar).key << (options_.smooth ? ", smooth" : ", flat") << " | "
    << solution_->GetNumberOfCells() << " elements";
  if (live_) {
    const auto& h = live_->history();
    s << " | " << live_->solverName() << ": " << live_->iterations() << " iterations, "
      << (h.empty() ? 0.0 : h.back()) << (live_->converged() ? " (converged)" : "")
      << (running_ ? " running" : "") << (ambient_ ? " + ambient" : "");
  } else if (options_.linksOf) {
    s << " | hierarchical solve, p: an element's links";
  } else {
    s << " | saved solution";
  }
  if (probeCount_ > 0) {
    s << " | " << probeCount_ << " probes";
    if (probesInside_ > 0) s << " (" << probesInside_ << " inside, hidden)";
    if (!probes_->GetVisibility()) s << " off";
  }
  if (!lastMessage_.empty()) s << "\n" << lastMessage_;
  status_->SetInput(s.str().c_str());
}

void SolutionViewer::say(const std::string& message) {
  lastMessage_ = message;
  logInfo(message);
  refreshStatus();
}

void SolutionViewer::drawLines(
    const std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>>& segments,
    const std::vector<std::array<unsigned char, 3>>& colour) {
  auto points = vtkSmartPointer<vtkPoints>::New();
  auto lines = vtkSmartPointer<vtkCellArray>::New();
  auto colours = vtkSmartPointer<vtkUnsignedCharArray>::New();
  colours->SetNumberOfComponents(3);
  colours->SetName("colour");
  for (size_t k = 0; k < segments.size(); ++k) {
    const vtkIdType a = points->InsertNextPoint(segments[k].first.data());
    const vtkIdType b = points->InsertNextPoint(segments[k].second.data());
    const vtkIdType line[2] = {a, b};
    lines->InsertNextCell(2, line);
    colours->InsertNextTypedTuple(colour[k].data());
  }
  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->SetPoints(points);
  data->SetLines(lines);
  data->GetCellData()->SetScalars(colours);
  auto* mapper = vtkPolyDataMapper::SafeDownCast(rays_->GetMapper());
  mapper->SetInputData(data);
  mapper->SetColorModeToDirectScalars();
  mapper->SetScalarModeToUseCellData();
  rays_->SetVisibility(!segments.empty());
}

void SolutionViewer::setRays(const std::vector<RaySegment>& rays) {
  std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> segments;
  std::vector<std::array<unsigned char, 3>> colours;
  for (const RaySegment& r : rays) {
    segments.emplace_back(r.from, r.to);
    colours.push_back(r.hit ? std::array<unsigned char, 3>{255, 220, 40}
                            : std::array<unsigned char, 3>{150, 150, 150});
  }
  rays_->GetProperty()->SetLineWidth(1);
  drawLines(segments, colours);
}

void SolutionViewer::setLinks(const std::vector<LinkSegment>& links) {
  // Yellow to surfaces, cyan to clusters; the links that bring little are dimmed, so the ones
  // that light the element stand out.
  double strongest = 0;
  for (const LinkSegment& l : links) strongest = std::max(strongest, l.share);
  std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> segments;
  std::vector<std::array<unsigned char, 3>> colours;
  for (const LinkSegment& l : links) {
    const double weight = 0.55 + 0.45 * (strongest > 0 ? std::sqrt(l.share / strongest) : 1.0);
    const double base[3] = {l.cluster ? 60.0 : 255.0, l.cluster ? 200.0 : 220.0,
                            l.cluster ? 255.0 : 40.0};
    std::array<unsigned char, 3> c;
    for (int i = 0; i < 3; ++i) c[i] = static_cast<unsigned char>(base[i] * weight);
    segments.emplace_back(l.from, l.to);
    colours.push_back(c);
  }
  rays_->GetProperty()->SetLineWidth(2);  // tens of links, not hundreds of rays
  drawLines(segments, colours);
}

void SolutionViewer::showRows(int element) {
  if (element < 0 || element >= solution_->GetNumberOfCells())
    throw InputError("element " + std::to_string(element) + " does not exist (the mesh has " +
                     std::to_string(solution_->GetNumberOfCells()) + " elements)");
  if (options_.linksOf) {
    const std::vector<LinkSegment> links = options_.linksOf(element);
    int clusters = 0;
    double strongest = 0;
    for (const LinkSegment& l : links) {
      clusters += l.cluster;
      strongest = std::max(strongest, l.share);
    }
    setLinks(links);
    say("element " + std::to_string(element) + ": " + std::to_string(links.size()) + " links, " +
        std::to_string(links.size() - clusters) + " to surfaces (yellow), " +
        std::to_string(clusters) + " to clusters (cyan); the strongest brings " +
        std::to_string(static_cast<int>(std::lround(100 * strongest))) + "%");
    return;
  }
  if (!live_) {
    say("a saved solution has no form factors: open the scene to see rays");
    return;
  }
  const std::vector<RaySegment> rays = live_->rowRays(element);
  int hits = 0;
  for (const RaySegment& r : rays) hits += r.hit;
  setRays(rays);
  say("element " + std::to_string(element) + ": " + std::to_string(rays.size()) + " rays, " +
      std::to_string(hits) + " reach a front face (yellow), the rest escape (grey)");
}

void SolutionViewer::printElement(int element) const {
  vtkCellData* cd = solution_->GetCellData();
  auto triple = [&](const char* name) {
    vtkDataArray* a = cd->GetArray(name);
    return "(" + format(a->GetComponent(element, 0)) + ", " + format(a->GetComponent(element, 1)) +
           ", " + format(a->GetComponent(element, 2)) + ")";
  };
  auto single = [&](const char* name) {
    return format(cd->GetArray(name)->GetComponent(element, 0));
  };
  std::printf(
      "element %d: patch %s, material %s, level %s, area %s\n  B %s W/m^2, L %s W/m^2/sr, unshot "
      "%s W\n",
      element, single(solution_array::patch).c_str(), single(solution_array::material).c_str(),
      single(solution_array::level).c_str(), single(solution_array::area).c_str(),
      triple(solution_array::radiosity).c_str(), triple(solution_array::radiance).c_str(),
      triple(solution_array::unshot).c_str());
  std::fflush(stdout);
}

void SolutionViewer::pickAt(int x, int y) {
  // Pick what is drawn (a hardware selection honours back-face culling, a ray picker would
  // return the invisible near wall of a room), on the mesh alone.
  const bool rays = rays_->GetVisibility(), outlines = outlines_->GetVisibility(),
             probes = probes_->GetVisibility();
  rays_->VisibilityOff();
  outlines_->VisibilityOff();
  probes_->VisibilityOff();
  auto selector = vtkSmartPointer<vtkHardwareSelector>::New();
  selector->SetRenderer(scene_);
  selector->SetArea(x, y, x, y);
  selector->SetFieldAssociation(vtkDataObject::FIELD_ASSOCIATION_CELLS);
  vtkSmartPointer<vtkSelection> selection;
  selection.TakeReference(selector->Select());
  rays_->SetVisibility(rays);
  outlines_->SetVisibility(outlines);
  probes_->SetVisibility(probes);
  int element = -1;
  for (unsigned i = 0; selection && i < selection->GetNumberOfNodes() && element < 0; ++i) {
    vtkSelectionNode* node = selection->GetNode(i);
    auto* ids = vtkIdTypeArray::SafeDownCast(node->GetSelectionList());
    if (node->GetProperties()->Get(vtkSelectionNode::PROP()) == mesh_.GetPointer() && ids &&
        ids->GetNumberOfValues() > 0)
      element = static_cast<int>(ids->GetValue(0));
  }
  if (element < 0) {
    say("nothing under the cursor to pick");
    return;
  }
  printElement(element);
  showRows(element);
}

void SolutionViewer::runTick() {
  if (!live_ || !running_) return;
  // Step for about a frame's time, then redraw.
  const auto start = std::chrono::steady_clock::now();
  while (!live_->converged() &&
         std::chrono::steady_clock::now() - start < std::chrono::milliseconds(40))
    live_->step();
  if (live_->converged()) {
    running_ = false;
    if (timer_ >= 0 && window_->GetInteractor())
      window_->GetInteractor()->DestroyTimer(timer_), timer_ = -1;
    say("solver converged after " + std::to_string(live_->iterations()) + " iterations");
  }
  refreshSolution();
}

bool SolutionViewer::handleKey(const std::string& key, int x, int y) {
  const bool noSolver =
      !live_ && (key == "space" || key == "g" || key == "b" || key == "a" || key == "l");
  if (noSolver) {
    say(options_.linksOf
            ? "the hierarchical solve is not stepped live: p shows an element's links"
            : "a saved solution has no solver to step: open the scene (radiosity view SCENE.obj)");
    return true;
  }
  if (key.size() == 1 && key[0] >= '1' && key[0] <= '9') {
    options_.scalar = static_cast<DisplayScalar>(key[0] - '1');
    refreshColours();
  } else if (key == "h") {
    help_->SetVisibility(!help_->GetVisibility());
  } else if (key == "v") {
    options_.smooth = !options_.smooth;
    refreshColours();
  } else if (key == "e") {
    mesh_->GetProperty()->SetEdgeVisibility(!mesh_->GetProperty()->GetEdgeVisibility());
  } else if (key == "o") {
    outlines_->SetVisibility(!outlines_->GetVisibility());
  } else if (key == "u") {
    mesh_->GetProperty()->SetBackfaceCulling(!mesh_->GetProperty()->GetBackfaceCulling());
  } else if (key == "p") {
    pickAt(x, y);
  } else if (key == "l") {
    if (live_->lastShooter() < 0)
      say("no shot yet (or not a shooting solver)");
    else
      showRows(live_->lastShooter());
  } else if (key == "x") {
    setRays({});
  } else if (key == "i") {
    if (probeCount_ == 0)
      say("no light probes: view DIR shows DIR/probes.bin (solve --probes), or use --probes FILE");
    else
      probes_->SetVisibility(!probes_->GetVisibility());
  } else if (key == "space") {
    if (live_->converged())
      say("converged: press b to restart from B = E");
    else
      live_->step();
    refreshSolution();
  } else if (key == "g") {
    running_ = !running_ && !live_->converged();
    vtkRenderWindowInteractor* interactor = window_->GetInteractor();
    if (running_ && interactor && timer_ < 0) timer_ = interactor->CreateRepeatingTimer(30);
    if (!running_ && interactor && timer_ >= 0) interactor->DestroyTimer(timer_), timer_ = -1;
    refreshStatus();
  } else if (key == "b") {
    live_->restart();
    say("restarted from B = E");
    refreshSolution();
  } else if (key == "a") {
    ambient_ = !ambient_;
    refreshSolution();
  } else if (key == "r") {
    resetCamera();
  } else {
    return false;
  }
  refreshStatus();
  return true;
}

void SolutionViewer::screenshot(const std::string& pngPath) {
  window_->SetOffScreenRendering(1);
  window_->SetSize(options_.width, options_.height);
  window_->Render();
  auto grab = vtkSmartPointer<vtkWindowToImageFilter>::New();
  grab->SetInput(window_);
  grab->SetInputBufferTypeToRGB();
  grab->ReadFrontBufferOff();
  grab->Update();
  auto png = vtkSmartPointer<vtkPNGWriter>::New();
  png->SetInputConnection(grab->GetOutputPort());
  png->SetCompressionLevel(9);  // documentation images: size matters more than the milliseconds
  png->WriteToMemoryOn();
  png->Write();
  vtkUnsignedCharArray* bytes = png->GetResult();
  if (!bytes || bytes->GetNumberOfValues() == 0) throw RuntimeFailure("VTK produced no PNG data");
  // As solve/render/bake: a pending interrupt writes nothing; one arriving from here on waits
  // until the PNG has its final name.
  throwIfInterrupted();
  OutputSection writing;
  AtomicFile file(pngPath, /*binary=*/true);
  file.stream().write(reinterpret_cast<const char*>(bytes->GetPointer(0)),
                      bytes->GetNumberOfValues());
  file.commit();
  logInfo("wrote " + pngPath + " (" + std::to_string(options_.width) + "x" +
          std::to_string(options_.height) + ")");
}

void SolutionViewer::setProbes(const std::vector<ProbeSh>& probes) {
  double bounds[6];
  solution_->GetBounds(bounds);
  const double diagonal =
      Eigen::Vector3d(bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4]).norm();
  const double radius = probeSphereRadius(probes, 0.02 * diagonal);
  auto* mapper = vtkPolyDataMapper::SafeDownCast(probes_->GetMapper());
  mapper->SetInputData(
      makeProbePolyData(probes, radius, toneMap_, probeSphereSegments(probes.size())));
  mapper->SetColorModeToDirectScalars();
  mapper->SetScalarModeToUsePointData();
  mapper->ScalarVisibilityOn();
  probeCount_ = static_cast<int>(probes.size());
  probesInside_ = 0;
  for (const ProbeSh& p : probes) probesInside_ += p.inside;
  probes_->SetVisibility(probeCount_ > 0);
  refreshStatus();
}

void SolutionViewer::interact() {
  auto interactor = vtkSmartPointer<vtkRenderWindowInteractor>::New();
  auto style = vtkSmartPointer<ViewerStyle>::New();
  style->setViewer(this);
  style->SetDefaultRenderer(scene_);
  interactor->SetInteractorStyle(style);
  interactor->SetRenderWindow(window_);
  window_->Render();
  interactor->Initialize();
  interactor->Start();
  running_ = false;
}

}  // namespace rad
