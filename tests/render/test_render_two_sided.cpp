// The camera sees a two-sided surface from behind: a quad facing down under a uniform sky, seen
// from above, shows its upper side's radiance ρL (B = ρπL exactly on an open plane; the preview
// shows B/π); one-sided it has no upper side and its back is black.
#include <gtest/gtest.h>

#include <memory>

#include "radiosity/pipeline/solve_pipeline.h"
#include "radiosity/render/image_renderer.h"
#include "radiosity/render/interpolated_preview.h"
#include "radiosity/render/render_scene.h"
#include "radiosity/scene/two_sided.h"
#include "tests/support/test_scenes.h"

namespace rad {
namespace {

const Rgb kRho{0.5, 0.4, 0.3};
const Rgb kSky{1, 2, 3};

ImageRgb viewFromAbove(bool twoSided) {
  Light sky;
  sky.type = LightType::Sky;
  sky.radiance = kSky;
  Scene scene = testing::greyScene(kRho, {sky});
  testing::addPolygon(scene, {{-1, 0, -1}, {1, 0, -1}, {1, 0, 1}, {-1, 0, 1}});  // facing down
  applyTwoSidedInput(scene, {twoSided, {}});
  addBackSides(scene);

  SolveOptions options;
  options.targetElements = 64;
  options.raysPerElement = 64;
  options.threads = 2;
  const SolveResult solved = solveScene(scene, options);
  const RayCaster caster(*solved.solution.mesh, solved.solution.scene);
  const RenderScene view(solved.solution.scene, *solved.solution.mesh, caster);
  const InterpolatedPreview preview(view, solved.solution.radiosity);
  Camera camera;
  camera.position = {0, 3, 0};
  camera.lookAt = {0, 0, 0};
  camera.up = {0, 0, 1};
  camera.vfovDegrees = 30;  // half-width 3·tan 15° = 0.8: every pixel sees the quad
  camera.width = camera.height = 8;
  RenderSettings settings;
  settings.samplesPerPixel = 1;
  settings.showProgress = false;
  return renderImage(camera, preview, settings).image;
}

TEST(RenderTwoSided, OneSidedQuadSeenFromBehindIsBlack) {
  for (const Rgb& p : viewFromAbove(false).pixels) EXPECT_EQ(p.maxComponent(), 0.0);
}

TEST(RenderTwoSided, TwoSidedQuadSeenFromBehindShowsItsUpperSide) {
  for (const Rgb& p : viewFromAbove(true).pixels)
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(p[c], kRho[c] * kSky[c], 1e-9);
}

}  // namespace
}  // namespace rad
