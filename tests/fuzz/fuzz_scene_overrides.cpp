// libFuzzer target: relight's override file through its one reader, loadSceneOverrides()
// (radiosity/scene/scene_overrides.h), against a fixed scene whose names include a shared one, an
// empty one, one with pointer escapes ("/", "~") and a light group named by digits. Every error
// must name the file; what it accepts must index real materials and lights, change something in
// each material, and hold only valid values (Kd in [0, 1], Ke and scales finite and >= 0).
// Findings: crashes, sanitizer reports, and any exception other than InputError.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "radiosity/core/errors.h"
#include "radiosity/scene/scene_overrides.h"
#include "tests/fuzz/fuzz_temp_dir.h"

namespace {

void check(bool ok, const char* what) {
  if (ok) return;
  std::fprintf(stderr, "fuzz_scene_overrides: %s\n", what);
  std::abort();
}

bool valid(const rad::Rgb& c) { return c.isFinite() && c.minComponent() >= 0; }

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const std::vector<std::string> materials = {"white", "red", "a/b~c", "", "red", "lamp"};
  static const std::vector<std::string> groups = {"lamp", "point1", "lamp", "7", "sky", ""};
  const std::string path =
      rad::fuzz::writeTemp("over.json", reinterpret_cast<const char*>(data), size);
  rad::SceneOverrides o;
  try {
    o = rad::loadSceneOverrides(path, materials, groups);
  } catch (const rad::InputError& e) {
    check(std::string(e.what()).find(path) != std::string::npos, "an error does not name the file");
    return 0;
  }
  for (const auto& [index, m] : o.materials) {
    check(index >= 0 && index < static_cast<int>(materials.size()), "no such material");
    check(m.diffuse || m.emission, "a material override that changes nothing");
    if (m.diffuse) check(valid(*m.diffuse) && m.diffuse->maxComponent() <= 1, "bad diffuse");
    if (m.emission) check(valid(*m.emission), "bad emission");
  }
  check(o.lightScale.size() == groups.size(), "not one scale per light");
  for (const rad::Rgb& s : o.lightScale) check(valid(s), "bad light scale");
  return 0;
}
