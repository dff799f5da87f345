#pragma once

namespace rad {

// The rays per diffuse hit of the eye passes over a radiosity solution (`--gather`,
// `--light-rays`); makeRadiosityIntegrator (radiosity_integrator.h) reads them to choose the pass:
//  - gatherRays 0, lightRays 0: the interpolated radiosity B/π at the first diffuse hit
//    (InterpolatedPreview);
//  - gatherRays 0, lightRays N: the direct light by N shadow rays at the hit plus the solution's
//    indirect part interpolated there (DirectIndirectSplit);
//  - gatherRays N > 0: direct light by shadow rays to the emitters plus N cosine-weighted gather
//    rays into the solution's reflected part (B − E)/π; the two share the direct light by multiple
//    importance sampling (a gather ray that reaches an emitter adds its MIS-weighted Ke). A gather
//    ray that lands on a diffuse surface closer than the size of the element it hits (a corner, a
//    contact) gathers once more from that point (one shadow and one cosine ray, MIS-weighted in
//    the same way) instead of taking the element's value (FinalGather).
struct FinalGatherOptions {
  int gatherRays = 64;
  // Shadow rays per diffuse eye hit; 0: as many as gatherRays (with gatherRays 0: the preview).
  // Fewer than gatherRays pays where the gather's indirect part, not the direct light, holds most
  // of the variance (the Cornell box: docs/benchmarks.md, "Error against time"); the MIS weights
  // count the rays of each kind (power heuristic with n·pdf), so any count stays unbiased.
  int lightRays = 0;

  // The one place the two counts decide the mode (the factory, the command line's reports):
  // shadow rays per hit, lightRays or else as many as gatherRays;
  int shadowRays() const { return lightRays > 0 ? lightRays : gatherRays; }
  // gatherRays 0 with lightRays: the direct light per hit, the indirect light the solution's;
  bool indirectFromSolution() const { return gatherRays == 0 && lightRays > 0; }
  // whether rays are cast per hit at all (otherwise the solution is interpolated there).
  bool castsRays() const { return gatherRays > 0 || lightRays > 0; }
};

}  // namespace rad
