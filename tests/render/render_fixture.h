#pragma once

#include <memory>
#include <string>

#include "radiosity/pipeline/solve_pipeline.h"
#include "radiosity/render/render_scene.h"
#include "radiosity/scene/obj_loader.h"

namespace rad::testing {

// A solved scene with its BVH and render view, for the render tests.
struct SolvedScene {
  SolveResult solved;
  std::unique_ptr<RayCaster> caster;
  std::unique_ptr<RenderScene> view;
};

inline std::unique_ptr<SolvedScene> solveForRender(const std::string& path, SolveOptions options) {
  auto s = std::make_unique<SolvedScene>();
  s->solved = solveScene(loadObjScene(path), options);
  s->caster = std::make_unique<RayCaster>(*s->solved.solution.mesh);
  s->view =
      std::make_unique<RenderScene>(s->solved.solution.scene, *s->solved.solution.mesh, *s->caster);
  return s;
}

}  // namespace rad::testing
