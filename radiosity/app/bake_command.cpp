// `radiosity bake SCENE.obj --out DIR`: the solution baked into a lightmap atlas and into exports
// that game engines and DCC tools load (glTF binary, OBJ + MTL, PLY vertex colours). The bake
// itself is radiosity::bake (bakeSolution); here are its options and the writing of its files.
#include <chrono>
#include <filesystem>
#include <functional>
#include <future>
#include <map>
#include <memory>
#include <optional>

#include "radiosity/app/baked_materials.h"
#include "radiosity/app/commands.h"
#include "radiosity/app/options/exposure_option.h"
#include "radiosity/app/options/gather_options.h"
#include "radiosity/app/options/option_rules.h"
#include "radiosity/app/options/solve_option_group.h"
#include "radiosity/bake/bake_files.h"
#include "radiosity/bake/bake_solution.h"
#include "radiosity/core/atomic_file.h"
#include "radiosity/core/errors.h"
#include "radiosity/core/interrupt.h"
#include "radiosity/core/log.h"
#include "radiosity/core/seconds_since.h"
#include "radiosity/output/gltf_export.h"
#include "radiosity/output/image_io.h"
#include "radiosity/output/lightmap_baked_mesh.h"
#include "radiosity/output/lightmap_confidence.h"
#include "radiosity/output/lightmap_content.h"
#include "radiosity/output/obj_export.h"
#include "radiosity/output/vertex_colors_ply.h"
#include "radiosity/pipeline/solution_source.h"
#include "radiosity/pipeline/thread_limit.h"
#include "radiosity/scene/lightmap_uv_check.h"
#include "radiosity/scene/scene_loader.h"

namespace rad {
namespace {

struct BakeOptions {
  SolveOptions solve;
  double texelSize = 0;     // --texel-size, scene units per texel; 0: not given
  double texelDensity = 0;  // --texel-density, texels per scene unit; 0: not given
  int lightmapSize = 0;     // --lightmap-size; 0: not given
  int padding = 2;
  int dilation = -1;  // -1: the padding
  double chartAngle = 30;
  bool noLightmap = false;
  bool sceneUvs = false;  // bake into the scene's own texture coordinates
  // Per texel: --gather, --light-rays; none: the solution interpolated.
  FinalGatherOptions gather = {0, 0};
  std::string solutionDir;  // --solution: reuse the solution `solve` saved there
  ExposureOption exposure;  // --exposure: fixed instead of automatic
  LightmapContent content = LightmapContent::Radiance;  // --lightmap-content
  bool directional = false;  // --directional: L1 SH texels beside the lightmap
  int directionalRays = 64;  // --directional-rays: hemisphere rays per texel
};

// What only the lightmap reads: with --no-lightmap (vertex colours only), an error when given.
// (--use-scene-uvs and --chart-angle exclude --no-lightmap on the command line, --directional
// has its own rule below.)
const char* const kLightmapOnlyOptions[] = {"--texel-size", "--texel-density",   "--lightmap-size",
                                            "--padding",    "--dilation",        "--gather",
                                            "--light-rays", "--lightmap-content"};

// Every bake option the chosen mode does not use, given, is an error saying why; so are values
// that cannot work together. Before anything is solved or written. Sets --dilation's default.
void checkBakeOptions(const CLI::App& command, BakeOptions& o) {
  finishSolveOptions(command, o.solve);
  o.exposure.check();
  checkGatherOptions(o.gather);
  if (o.noLightmap)
    for (const char* name : kLightmapOnlyOptions)
      refuseIfGiven(command, name, "--no-lightmap bakes vertex colours only, no lightmap");
  if (command.count("--directional-rays") > 0 && !o.directional)
    throw InputError(
        "--directional-rays sets the rays of --directional's texels: add --directional");
  if (o.directional && o.noLightmap)
    throw InputError(
        "--directional with --no-lightmap: the directional texels are lightmap pages beside "
        "lightmap.exr; drop --no-lightmap");
  if (o.directional && o.solve.lightGroups)
    throw InputError(
        "--directional with --light-groups: the directional texels hold the whole scene's light, "
        "not one layer per group; bake the groups and the directional lightmap separately");
  if (o.solve.lightGroups && o.gather.castsRays())
    throw InputError(
        "--gather with --light-groups: the per-texel gather samples every light at once, so it "
        "cannot split its direct light into the groups; bake the layers without --gather (or "
        "refine the mesh with --element-size for sharper shadows)");
  if (o.dilation < 0) o.dilation = o.padding;
  if (o.dilation > o.padding)
    throw InputError("--dilation " + std::to_string(o.dilation) + " exceeds --padding " +
                     std::to_string(o.padding) +
                     ": dilated texels of neighbouring charts would meet");
}

// What the bake makes of the solution, from the options checked by runBake.
BakeSpec bakeSpec(const BakeOptions& o) {
  BakeSpec spec;
  spec.scenePath = o.solve.scenePath;
  spec.layout = {o.texelSize, o.texelDensity, o.lightmapSize, o.padding, o.chartAngle, o.sceneUvs};
  spec.lightmap = !o.noLightmap;
  spec.dilation = o.dilation;
  spec.gather = o.gather;
  spec.content = o.content;
  spec.directional = o.directional;
  spec.directionalRays = o.directionalRays;
  spec.seed = o.solve.seed;
  spec.exposure = o.exposure.value();
  return spec;
}

// The bake's files in the output directory under temporary names; commit() gives them all their
// names at once, and a failure before that leaves none. The EXR pages are compressed on
// OpenEXR's own threads while the rest is encoded and written (a large page takes a few tenths of
// a second).
class BakeFileSet {
 public:
  explicit BakeFileSet(const std::string& dir) : dir_(dir) { ensureDirectory(dir); }

  std::ostream& open(const std::string& name, bool binary) {
    files_.push_back(std::make_unique<AtomicFile>((dir_ / name).string(), binary));
    return files_.back()->stream();
  }
  void png(const std::string& name, const std::vector<std::uint8_t>& bytes) {
    open(name, true)
        .write(reinterpret_cast<const char*>(bytes.data()),
               static_cast<std::streamsize>(bytes.size()));
  }
  // `image` must outlive the set.
  void exr(const std::string& name, const ImageRgb& image, std::vector<ExrChannel> extra = {}) {
    exrFiles_.push_back(std::make_unique<AtomicPath>((dir_ / name).string()));
    exrWrites_.push_back([file = exrFiles_.back().get(), &image, extra = std::move(extra)] {
      writeExr(*file, image, extra);
    });
  }
  // The EXRs queued so far, on a thread of their own (on this one, at commit, when `inParallel`
  // is false: --threads 1).
  void startExrs(bool inParallel) {
    writingExrs_ = std::async(inParallel ? std::launch::async : std::launch::deferred, [this] {
      for (const auto& write : exrWrites_) write();
    });
  }
  void commit() {
    if (writingExrs_.valid()) writingExrs_.get();  // rethrows a failed write
    std::vector<AtomicFile*> set;
    for (auto& f : files_) set.push_back(f.get());
    std::vector<AtomicPath*> exrSet;
    for (auto& f : exrFiles_) exrSet.push_back(f.get());
    commitAll(set, exrSet);
  }

 private:
  std::filesystem::path dir_;
  std::vector<std::unique_ptr<AtomicFile>> files_;
  // The temporary EXR files go only once their writes are done: `writingExrs_`, destroyed first,
  // waits for them.
  std::vector<std::unique_ptr<AtomicPath>> exrFiles_;
  std::vector<std::function<void()>> exrWrites_;
  std::future<void> writingExrs_;
};

// Every linear page: the lightmap with its "error" channel, each light group's, the directional
// coefficients.
void queueExrs(const BakeResult& baked, const std::vector<LightLayer>& layers, BakeFileSet& files) {
  const int pages = baked.layout.pages;
  for (int page = 0; page < static_cast<int>(baked.lightmaps.size()); ++page)
    files.exr(lightmapFileName(page, pages, "exr"), baked.lightmaps[page].radiance,
              {{"error", errorChannel(baked.errorPages[page])}});
  for (size_t g = 0; g < baked.layerLightmaps.size(); ++g)
    for (int page = 0; page < static_cast<int>(baked.layerLightmaps[g].size()); ++page)
      files.exr(groupFileName(layers[g].group, lightmapFileName(page, pages, "exr")),
                baked.layerLightmaps[g][page].radiance);
  for (size_t page = 0; page < baked.directionalPages.size(); ++page)
    for (int k = 0; k < 4; ++k)
      files.exr(directionalFileName(static_cast<int>(page), pages,
                                    std::string(directionalCoefficientNames()[k]) + ".exr"),
                baked.directionalPages[page].coefficients[k].radiance);
}

// What the baked glTF shows besides its geometry: the lightmap pages as PNG over the scene's
// base colours (their textures on TEXCOORD_0), and each light group's layer.
BakedLook bakedLook(const Solution& solution, const BakeResult& baked, const BakedMesh& mesh,
                    bool lightmap) {
  BakedLook look;
  if (lightmap) look = bakedBaseColours(solution.scene, !mesh.textureUvs.empty());
  for (const Lightmap& page : baked.lightmaps)
    look.lightmapPages.push_back(encodePng(page.radiance, baked.toneMap));
  for (size_t g = 0; g < solution.layers.size(); ++g) {
    const LightGroup& group = solution.layers[g].group;
    BakedLayer layer;
    layer.name = group.name;
    for (int v : mesh.sourceVertex) layer.radiance.push_back(baked.layerVertexRadiance[g][v]);
    for (size_t page = 0; lightmap && page < baked.layerLightmaps[g].size(); ++page) {
      layer.lightmapPages.push_back(
          encodePng(baked.layerLightmaps[g][page].radiance, baked.toneMap));
      layer.exrFiles.push_back(groupFileName(
          group, lightmapFileName(static_cast<int>(page), baked.layout.pages, "exr")));
    }
    look.layers.push_back(std::move(layer));
  }
  return look;
}

// The 8-bit and mesh files: vertex colours, the glTF, the PNG pages, each light group's, the
// directional pages' direction PNG, the OBJ + MTL over the lightmap.
void writeMeshesAndPngs(const Solution& solution, const BakeResult& baked, const BakeOptions& o,
                        BakeReport& report, BakeFileSet& files) {
  const PatchMesh& mesh = *solution.mesh;
  const int pages = baked.layout.pages;
  std::vector<std::string> materialNames;
  for (const Material& m : solution.scene.materials) materialNames.push_back(m.name);
  std::vector<char> backSidePatches;  // one patch per scene polygon
  for (const ScenePolygon& polygon : solution.scene.polygons)
    backSidePatches.push_back(polygon.backSideOf >= 0);
  const BakedMesh bakedMesh =
      makeBakedMesh(mesh, baked.interpolation, baked.vertexRadiance,
                    o.noLightmap ? nullptr : &baked.layout, materialNames, backSidePatches);
  const BakedLook look = bakedLook(solution, baked, bakedMesh, !o.noLightmap);
  if (!o.noLightmap) report.baseColourImages = look.images.size();
  writeVertexColorsPly(files.open("vertex_colors.ply", true), baked.interpolation, mesh,
                       baked.vertexRadiance, baked.toneMap);
  writeBakedGlb(files.open("scene_baked.glb", true), bakedMesh, look, baked.toneMap, o.content);
  std::vector<std::string> pngNames;
  for (int page = 0; page < static_cast<int>(look.lightmapPages.size()); ++page) {
    pngNames.push_back(lightmapFileName(page, pages, "png"));
    files.png(pngNames.back(), look.lightmapPages[page]);
  }
  for (size_t g = 0; g < solution.layers.size(); ++g) {
    const LightGroup& group = solution.layers[g].group;
    writeVertexColorsPly(files.open(groupFileName(group, "vertex_colors.ply"), true),
                         baked.interpolation, mesh, baked.layerVertexRadiance[g], baked.toneMap);
    for (size_t page = 0; page < look.layers[g].lightmapPages.size(); ++page)
      files.png(groupFileName(group, lightmapFileName(static_cast<int>(page), pages, "png")),
                look.layers[g].lightmapPages[page]);
  }
  for (size_t page = 0; page < baked.directionalPages.size(); ++page)
    files.png(directionalFileName(static_cast<int>(page), pages, "direction.png"),
              encodePng(baked.directionalPages[page].direction, ToneMap{1}));
  if (!o.noLightmap) {
    std::ostream& obj = files.open("scene_baked.obj", false);
    writeBakedObj(obj, files.open("scene_baked.mtl", false), bakedMesh, "scene_baked.mtl",
                  pngNames);
  }
}

// Every file of the bake, bake.json last, all taking their names at once.
void writeBakeFiles(const Solution& solution, BakeResult& baked, const BakeOptions& o,
                    bool exrsInParallel, std::chrono::steady_clock::time_point start) {
  throwIfInterrupted();
  OutputSection writing;  // Ctrl-C now waits until every file has its final name (or none has)
  BakeFileSet files(o.solve.outputDir);
  queueExrs(baked, solution.layers, files);
  files.startExrs(exrsInParallel);
  writeMeshesAndPngs(solution, baked, o, baked.report, files);
  baked.report.exportSeconds = secondsSince(start);
  files.open("bake.json", false) << bakeJson(baked.report).dump(2) << "\n";
  files.commit();
}

void runBake(const CLI::App& command, BakeOptions& o) {
  checkBakeOptions(command, o);
  // --threads caps the whole bake (gather, rasterising, EXR compression), not the solve alone.
  const ThreadLimit threadLimit(o.solve.threads);
  const int threads = threadLimit.threads();
  // The scene's UVs are checked before the solve, so a bad layout fails in seconds.
  const auto loadStart = std::chrono::steady_clock::now();
  Scene scene =
      loadScene(o.solve.scenePath, o.solve.lights, o.solve.twoSided, o.solve.unreadableTextures);
  if (o.sceneUvs) checkLightmapUvs(scene);
  const double loadSeconds = secondsSince(loadStart);
  // Whether the charts fit is decided before the solve (planLightmap), so a lightmap size that
  // cannot hold them fails in seconds. With --solution nothing is solved (a solution that does
  // not fit is refused in seconds): the charts are laid out once, on the saved solution's mesh.
  const BakeSpec spec = bakeSpec(o);
  LightmapPlan plan;
  if (!o.noLightmap && o.solutionDir.empty()) plan = planLightmap(scene, o.solve, spec.layout);
  // A solution `solve` (or an earlier render) saved in --out is reused when it matches.
  SolveResult result =
      solveOrReuse(std::move(scene), o.solve,
                   {o.solutionDir, o.solve.outputDir, o.gather.indirectFromSolution()});
  result.report.times.load = loadSeconds;
  result.report.times.total += loadSeconds;
  const auto start = std::chrono::steady_clock::now();
  BakeResult baked = bakeSolution(result, o.solve, spec, plan);
  writeBakeFiles(result.solution, baked, o, threads > 1, start);
  logInfo("baked " + o.solve.scenePath + " into " + o.solve.outputDir + " in " +
          std::to_string(secondsSince(start)) + " s after the solve");
}

}  // namespace

void registerBakeCommand(CLI::App& app, CommandAction& run) {
  auto o = std::make_shared<BakeOptions>();
  CLI::App* bake =
      app.add_subcommand("bake", "Solve, then bake a lightmap atlas and glTF/OBJ/PLY exports");
  bake->add_option("scene", o->solve.scenePath,
                   std::string(kSceneFileHelp) + "; materials from its MTL or glTF")
      ->required();
  bake->add_option("--out", o->solve.outputDir, "Output directory (created if missing)")
      ->required();
  addSolveOptions(*bake, o->solve);
  auto* texel = bake->add_option("--texel-size", o->texelSize,
                                 "Lightmap texel size in scene units (pages grow to fit)")
                    ->check(positiveNumber());
  bake->add_option(
          "--texel-density", o->texelDensity,
          "Lightmap texels per scene unit (default: " + formatNumber(kDefaultLightmapTexels) +
              " texels over the scene's surface); more pages when one does not hold them")
      ->check(positiveNumber())
      ->excludes(texel);
  bake->add_option("--lightmap-size", o->lightmapSize,
                   "Alone: the side of one square lightmap page, at the densest texels that fit; "
                   "with --texel-density/--texel-size: the largest page side (default " +
                       std::to_string(kDefaultMaxLightmapPage) + ")")
      ->check(CLI::Range(8, 16384));
  bake->add_option("--padding", o->padding,
                   "Empty texels around each chart, each side (>= --dilation)")
      ->default_val(o->padding)
      ->check(CLI::Range(1, 64));
  bake->add_option("--dilation", o->dilation,
                   "Rings of texels filled around each chart (default: --padding)")
      ->check(CLI::Range(0, 64));
  addGatherOptions(*bake, o->gather, "texel (over its footprint, for sharp shadows)");
  auto* angle = bake->add_option("--chart-angle", o->chartAngle,
                                 "Largest normal angle within one chart, degrees")
                    ->default_val(o->chartAngle)
                    ->check(CLI::Range(0.0, 89.0));
  auto* noLightmap =
      bake->add_flag("--no-lightmap,--vertex-colors-only", o->noLightmap,
                     "Vertex colours only: vertex_colors.ply and an unlit scene_baked.glb");
  bake->add_flag("--use-scene-uvs", o->sceneUvs,
                 "Bake into the scene's own texture coordinates (every face needs 'vt', in [0, 1], "
                 "without overlaps) instead of generating lightmap UVs; charts are its UV islands")
      ->excludes(angle)
      ->excludes(noLightmap);
  o->exposure.add(*bake,
                  "Exposure of the 8-bit outputs (lightmap.png, vertex colours, the glTF): "
                  "display = clamp(exposure × radiance); default: the 99th percentile of the lit "
                  "surfaces' radiance maps to 1 (emitters excluded)");
  addChoiceOption(*bake, "--lightmap-content", o->content, lightmapContentTable(),
                  "What the lightmap holds: radiance (outgoing, textures included: display as "
                  "is) or irradiance (incident light / pi without the surface's albedo, for "
                  "engines that multiply it by the base colour; 0 where the reflectance is 0)");
  bake->add_flag("--light-groups", o->solve.lightGroups,
                 "One layer per light group (each emissive material; each light, or the lights "
                 "file's \"group\"; --sky, --sun): group_NAME_lightmap.exr/.png and "
                 "group_NAME_vertex_colors.ply beside the whole, and _LIGHT_GROUP_i in the glb, "
                 "so an engine can dim or recolour each group without a re-bake");
  bake->add_flag("--directional", o->directional,
                 "Directional lightmaps for normal-mapped surfaces: per texel the L1 spherical "
                 "harmonics of the incident light (lightmap_sh_L0/L1x/L1y/L1z.exr, world axes, "
                 "W/m^2) and lightmap_direction.png; see docs/baking.md");
  bake->add_option("--directional-rays", o->directionalRays,
                   "Hemisphere rays per texel of --directional")
      ->default_val(o->directionalRays)
      ->check(CLI::Range(1, 65536));
  bake->add_option("--solution", o->solutionDir,
                   "Reuse the solution `radiosity solve` wrote into this directory (same scene and "
                   "solve options) instead of solving");
  addCommonFlags(*bake);
  bake->callback([&run, bake, o] { run = [bake, o] { runBake(*bake, *o); }; });
}

}  // namespace rad
