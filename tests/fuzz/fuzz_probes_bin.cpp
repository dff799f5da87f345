// libFuzzer target: probes.bin, the light probes of `solve --probes` that `radiosity view` shows,
// through its one reader, readProbesBinary() (radiosity/render/light_probes.h). Every error must
// be an InputError naming the file; a file it accepts must hold at most kMaxProbes probes with
// finite positions and coefficients, and written back with writeProbesBinary it must give the
// same bytes (the layout has no slack: f32 values, flags 0 or 1). Findings: crashes, sanitizer
// reports, and any exception other than InputError.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "radiosity/core/errors.h"
#include "radiosity/render/light_probes.h"
#include "tests/fuzz/fuzz_temp_dir.h"

namespace {

void check(bool ok, const char* what) {
  if (ok) return;
  std::fprintf(stderr, "fuzz_probes_bin: %s\n", what);
  std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path =
      rad::fuzz::writeTemp("probes.bin", reinterpret_cast<const char*>(data), size);
  std::optional<std::vector<rad::ProbeSh>> probes;
  try {
    probes = rad::readProbesBinary(path);
  } catch (const rad::InputError& e) {
    check(e.file() == path, "an error does not name the file");
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fuzz_probes_bin: not an InputError: %s\n", e.what());
    std::abort();
  }
  check(probes->size() <= rad::kMaxProbes, "more probes than the limit");
  check(size == 12 + 124 * probes->size(), "the file's length is not the count's");
  for (const rad::ProbeSh& p : *probes) {
    check(p.position.allFinite(), "a position is not finite");
    for (const rad::Rgb& c : p.coefficients) check(c.isFinite(), "a coefficient is not finite");
  }
  std::ostringstream again;
  rad::writeProbesBinary(again, *probes);
  check(again.str() == std::string(reinterpret_cast<const char*>(data), size),
        "written back, the probes differ from the file");
  return 0;
}
