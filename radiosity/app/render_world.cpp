#include "radiosity/app/render_world.h"

#include <chrono>
#include <optional>

#include "radiosity/core/log.h"
#include "radiosity/core/seconds_since.h"
#include "radiosity/scene/scene_loader.h"
#include "radiosity/scene/scene_mesh.h"

namespace rad {
namespace {
using Clock = std::chrono::steady_clock;
}  // namespace

RenderWorld::RenderWorld(SolveOptions solve, const std::string& cameraFile, SolutionSource source)
    : solve_(std::move(solve)), source_(std::move(source)) {
  if (!cameraFile.empty()) motionSpec_ = loadMotionSpec(cameraFile);
}

RenderWorld::~RenderWorld() = default;

void RenderWorld::skip(const std::string& what, const std::string& why) {
  for (const SkipNote& s : skipped_)
    if (s.what == what) return;
  logInfo("skipped: " + what + " (" + why + ")");
  skipped_.push_back({what, why});
}

RenderWorld::View RenderWorld::viewFor(const RenderMethod& method) {
  if (method.needsSolve) {
    if (!solved_) {
      const auto t = Clock::now();
      Scene scene =
          loadScene(solve_.scenePath, solve_.lights, solve_.twoSided, solve_.unreadableTextures);
      requireEmitter(scene);
      solved_ = std::make_unique<SolveResult>(solveOrReuse(std::move(scene), solve_, source_));
      for (const SkipNote& note : solved_->report.skipped)  // logged by solveOrReuse
        if (note.what == "radiosity solve") skipped_.push_back(note);
      solveSeconds_ += secondsSince(t);
      const auto b = Clock::now();
      const Solution& solution = solved_->solution;
      solvedCaster_ = std::make_unique<RayCaster>(*solution.mesh, solution.scene);
      solvedView_ = std::make_unique<RenderScene>(solution.scene, *solution.mesh, *solvedCaster_);
      bvhSeconds_ += secondsSince(b);
    }
    if (!motionSpec_.empty())
      skip("motion blur for --method " + method.name, "only methods that sample time render it");
    return {solvedView_.get(), &solved_->solution.radiosity, &solved_->solution.directIrradiance};
  }

  if (!scene_) {
    scene_ = std::make_unique<Scene>(
        loadScene(solve_.scenePath, solve_.lights, solve_.twoSided, solve_.unreadableTextures));
    requireEmitter(*scene_);
    mesh_ = std::make_unique<PatchMesh>(buildPatchMesh(*scene_));
    skip("radiosity solve", "--method " + method.name + " needs only the scene's triangles");
  }
  if (method.usesMotion && !motionSpec_.empty()) {
    if (!motionView_) {
      motion_ = std::make_unique<SceneMotion>(*scene_, *mesh_, motionSpec_);
      const auto b = Clock::now();
      motionCaster_ = std::make_unique<RayCaster>(*mesh_, *scene_, &motion_->vertices());
      motionView_ = std::make_unique<RenderScene>(*scene_, *mesh_, *motionCaster_, motion_.get());
      bvhSeconds_ += secondsSince(b);
      logInfo("motion blur: " + std::to_string(motionSpec_.objects.size()) + " moving object(s), " +
              std::to_string(motion_->movingElements()) + " elements, shutter [" +
              std::to_string(motionSpec_.shutterOpen) + ", " +
              std::to_string(motionSpec_.shutterClose) + "]");
    }
    return {motionView_.get(), nullptr};
  }
  if (!motionSpec_.empty())
    skip("motion blur for --method " + method.name, "only methods that sample time render it");
  if (!view_) {
    const auto b = Clock::now();
    caster_ = std::make_unique<RayCaster>(*mesh_, *scene_);
    view_ = std::make_unique<RenderScene>(*scene_, *mesh_, *caster_);
    bvhSeconds_ += secondsSince(b);
  }
  return {view_.get(), nullptr};
}

}  // namespace rad
