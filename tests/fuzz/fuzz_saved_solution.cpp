// libFuzzer target: a saved solution (solution.json and the elements CSV it names) through its one
// reader, loadSavedSolution() (radiosity/pipeline/saved_solution.h), as bake, render and view
// reach it with --solution. The input is solution.json, then a line "%%", then the CSV; the text
// $FINGERPRINT in it becomes the fixed scene's fingerprint, so that inputs get past the
// fingerprint to the relit entry's overrides and the CSV's rows. The scene: a small room with a
// lamp material and a sun and a sky. Every error must be an InputError naming solution.json or the
// CSV; a solution it accepts holds one finite, non-negative B per element of the re-meshed scene,
// E_d (from the CSV's Ed columns) either not at all or one finite, non-negative value per element,
// an exposure (from the CSV's buried cells, or probe rays) and the scene's lights. Findings:
// crashes, sanitizer reports, and any other exception.
#include <Eigen/Core>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>

#include "radiosity/core/errors.h"
#include "radiosity/pipeline/saved_solution.h"
#include "radiosity/scene/lights.h"
#include "radiosity/scene/obj_loader.h"
#include "tests/fuzz/fuzz_temp_dir.h"

namespace {

void check(bool ok, const char* what) {
  if (ok) return;
  std::fprintf(stderr, "fuzz_saved_solution: %s\n", what);
  std::abort();
}

// A 2 m room open at the front, a lamp patch under its ceiling, red and white walls.
constexpr const char* kObj = R"(mtllib room.mtl
v 0 0 0
v 2 0 0
v 2 0 2
v 0 0 2
v 0 2 0
v 2 2 0
v 2 2 2
v 0 2 2
v 0.8 1.99 0.8
v 1.2 1.99 0.8
v 1.2 1.99 1.2
v 0.8 1.99 1.2
usemtl white
f 1 4 3 2
f 5 6 7 8
f 1 2 6 5
usemtl red
f 1 5 8 4
f 2 3 7 6
usemtl lamp
f 9 10 11 12
)";
constexpr const char* kMtl = R"(newmtl white
Kd 0.7 0.7 0.7
newmtl red
Kd 0.6 0.1 0.1
newmtl lamp
Kd 0.5 0.5 0.5
Ke 10 10 10
)";

struct Fixture {
  rad::Scene scene;
  rad::SolveOptions options;
  std::string fingerprint;
};

const Fixture& fixture() {
  static const Fixture f = [] {
    Fixture x;
    std::ofstream(rad::fuzz::tempDir() / "room.mtl") << kMtl;
    const std::string obj = (rad::fuzz::tempDir() / "room.obj").string();
    std::ofstream(obj) << kObj;
    x.scene = rad::loadObjScene(obj);
    x.scene.lights = {rad::sunLight(Eigen::Vector3d(0.3, -1, 0.2), rad::Rgb(3, 3, 3)),
                      rad::skyLight(rad::Rgb(0.2, 0.3, 0.5))};
    x.options.scenePath = obj;
    x.options.elementSize = 1.2;
    x.fingerprint = rad::solutionFingerprint(x.scene, x.options);
    return x;
  }();
  return f;
}

std::string withFingerprint(std::string text, const std::string& fingerprint) {
  const std::string placeholder = "$FINGERPRINT";
  for (size_t at = text.find(placeholder); at != std::string::npos;
       at = text.find(placeholder, at + fingerprint.size()))
    text.replace(at, placeholder.size(), fingerprint);
  return text;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const Fixture& f = fixture();
  const std::string input(reinterpret_cast<const char*>(data), size);
  const std::string separator = "\n%%\n";
  const size_t split = input.find(separator);
  const std::string json = withFingerprint(input.substr(0, split), f.fingerprint);
  const std::string csv =
      split == std::string::npos ? std::string() : input.substr(split + separator.size());
  const std::string dir = (rad::fuzz::tempDir() / "solution").string();
  std::filesystem::create_directories(dir);
  const std::string jsonPath =
      rad::fuzz::writeTemp("solution/solution.json", json.data(), json.size());
  rad::fuzz::writeTemp("solution/elements.csv", csv.data(), csv.size());

  std::string whyNot;
  std::optional<rad::SolveResult> result;
  try {
    result = rad::loadSavedSolution(dir, f.scene, f.options, whyNot);
  } catch (const rad::InputError& e) {
    // The relit entry may name another CSV beside solution.json, which this harness never writes.
    check(e.file() == jsonPath || e.file().rfind(dir + "/", 0) == 0,
          "an error does not name solution.json or its CSV");
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fuzz_saved_solution: not an InputError: %s\n", e.what());
    std::abort();
  }
  if (!result) {
    check(!whyNot.empty(), "refused without saying why");
    return 0;
  }
  const rad::Solution& s = result->solution;
  check(s.mesh != nullptr && s.radiosity.size() == static_cast<size_t>(s.mesh->elementCount()),
        "not one B per element");
  for (const rad::Rgb& b : s.radiosity) check(b.isFinite() && b.minComponent() >= 0, "bad B");
  check(s.directIrradiance.empty() || s.directIrradiance.size() == s.radiosity.size(),
        "E_d neither absent nor one per element");
  for (const rad::Rgb& d : s.directIrradiance)
    check(d.isFinite() && d.minComponent() >= 0, "bad E_d");
  check(s.scene.lights.size() == f.scene.lights.size(), "the lights changed in number");
  check(s.scene.materials.size() == f.scene.materials.size(), "the materials changed in number");
  check(result->report.reusedSavedSolution, "not reported as reused");
  // The exposure, read from the CSV's buried cells or found by probe rays: a share of each
  // element's area in (0, 1].
  check(s.exposure != nullptr, "no exposure");
  for (int e = 0; e < s.mesh->elementCount(); ++e) {
    const double fraction = s.exposure->exposedFraction(e);
    check(fraction > 0 && fraction <= 1, "an exposed fraction outside (0, 1]");
  }
  return 0;
}
