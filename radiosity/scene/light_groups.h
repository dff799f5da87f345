#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "radiosity/scene/scene.h"

namespace rad {

// One light group of `bake --light-groups`: the emitters and lights whose light its layer holds.
// The radiosity solution is linear in the emission, so each group is solved on its own over the
// same form factors and the layers sum to the whole; an engine can dim or recolour each layer at
// run time without a re-bake.
struct LightGroup {
  std::string name;            // as the scene or the lights file names it
  std::string fileName;        // `name` with every character but [A-Za-z0-9._-] as '_'
  std::vector<int> materials;  // emissive materials (Scene::materials indices)
  std::vector<size_t> lights;  // Scene::lights indices
};

// The scene's light groups, in order of first appearance (emissive materials first, then the
// lights): each emissive material is a group named after it; each light joins the group its
// `group` names (the lights file's "group", a glTF light's name, "sky" / "sun" for the
// shortcuts) — a material's name too, so a lamp can share its fixture's group — or, unnamed, a
// group of its own, "<type><index>" (e.g. "point2", the index in the scene's lights). Throws
// InputError naming the scene when two groups' names give the same file name.
std::vector<LightGroup> lightGroups(const Scene& scene);

}  // namespace rad
