#pragma once

#include <vtkSmartPointer.h>

#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "radiosity/output/tone_map.h"
#include "viewer/display_scalars.h"
#include "viewer/link_segment.h"
#include "viewer/live_solution.h"
#include "viewer/scene_camera.h"

class vtkActor;
class vtkObject;
class vtkPolyData;
class vtkPolyDataMapper;
class vtkRenderer;
class vtkRenderWindow;
class vtkScalarBarActor;
class vtkTextActor;

namespace rad {

class ConvergenceChart;
struct ProbeSh;

// The window split left to right into the 3D view, the scalar bar's strip and the convergence
// panel, as fractions of the window's width (SolutionViewer::layoutFor states the rule).
struct ViewerLayout {
  double sceneRight = 1;  // the 3D view: [0, sceneRight]
  double barRight = 1;    // the scalar bar: [sceneRight, barRight]; empty when the bar is hidden
  bool chart = false;     // the convergence panel: [barRight, 1]
  int barFontSize = 12;
};

struct ViewerOptions {
  DisplayScalar scalar = DisplayScalar::Colour;
  bool smooth = false;        // vertex colours interpolated, instead of flat elements
  bool edges = false;         // element edges
  bool outlines = false;      // patch outlines
  bool chart = true;          // the convergence panel, when there is a history
  bool cullBackFaces = true;  // surfaces are one-sided: see into closed rooms
  bool help = true;           // the key overlay (interactive window)
  int width = 1280, height = 720;
  std::optional<Camera> camera;  // default: frame the bounding box
  int pickElement = -1;          // draw this element's form-factor rays (or links) from the start
  LinksOfElement linksOf;        // a hierarchical solve's links: what picking draws; empty: none
  double tolerance = 0;          // drawn on the convergence chart
  int stopAfter = -1;            // >= 0: the live solver restarted and stepped this often
  std::string title = "radiosity";
};

// The solution on screen: the mesh coloured by a scalar, edges, patch outlines, picked rays,
// a scalar bar, the key overlay and the convergence chart. With a LiveSolution the keys step the
// solver and the colours follow; without one (a saved solution) those keys say so.
class SolutionViewer {
 public:
  SolutionViewer(vtkSmartPointer<vtkPolyData> solution, ToneMap toneMap, LiveSolution* live,
                 ViewerOptions options);
  ~SolutionViewer();
  SolutionViewer(const SolutionViewer&) = delete;
  SolutionViewer& operator=(const SolutionViewer&) = delete;

  // Renders off-screen at the options' size and writes a PNG atomically.
  void screenshot(const std::string& pngPath);
  // Opens the window and returns when it is closed.
  void interact();
  // Shows light probes as spheres (probe_polydata.h: radiance probeIrradiance(n)/π under this
  // viewer's tone map; probes inside geometry hidden); key i toggles them. Replaces any shown.
  void setProbes(const std::vector<ProbeSh>& probes);

  // Key handling (viewer_style.cpp forwards keys, picks and timer ticks here).
  bool handleKey(const std::string& key, int x, int y);  // false: not ours
  void runTick();
  bool running() const { return running_; }
  void pickAt(int x, int y);
  void showRows(int element);
  static std::string keyHelp();
  // The layout of a window this many pixels wide and high; `chart`: there is a curve to show.
  static ViewerLayout layoutFor(int width, int height, bool chart);

 private:
  void build();
  void layout();  // from the window's current size; run before every render
  void onRenderStart(vtkObject*, unsigned long, void*) { layout(); }
  void refreshColours();
  void refreshSolution();  // after the live solver moved
  void refreshStatus();
  void refreshChart();
  void setRays(const std::vector<RaySegment>& rays);
  void setLinks(const std::vector<LinkSegment>& links);
  // Lines in the rays' actor, one colour each; hidden when empty.
  void drawLines(const std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>>& lines,
                 const std::vector<std::array<unsigned char, 3>>& colours);
  void printElement(int element) const;
  void resetCamera();
  void say(const std::string& message);

  vtkSmartPointer<vtkPolyData> solution_;
  ToneMap toneMap_;
  LiveSolution* live_;
  ViewerOptions options_;
  bool ambient_ = false;
  bool running_ = false;
  int timer_ = -1;
  std::string lastMessage_;

  vtkSmartPointer<vtkRenderWindow> window_;
  vtkSmartPointer<vtkRenderer> scene_, barStrip_;
  int laidOut_[2] = {0, 0};  // the window size layout() last saw
  vtkSmartPointer<vtkPolyDataMapper> meshMapper_;
  vtkSmartPointer<vtkActor> mesh_, outlines_, rays_, probes_;
  int probeCount_ = 0, probesInside_ = 0;
  vtkSmartPointer<vtkScalarBarActor> scalarBar_;
  vtkSmartPointer<vtkTextActor> help_, status_;
  ConvergenceChart* chart_ = nullptr;
};

}  // namespace rad
