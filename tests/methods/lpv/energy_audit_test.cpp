// An energy audit of every propagation variant under every kind of punctual light (issue 42), on
// the closed Cornell box (the built-in one) and an open scene (experiments/scenes/open_box.obj:
// no ceiling, no front wall), on the CPU backend (every strategy's CPU kernel is its GL kernel's
// shared GLSL, and the GL kernels are compared with them elsewhere):
//   - injection: the flux the light grid holds after injection equals the reflective shadow
//     maps' reflected flux, for every light type (a point light's six cube-face views, a spot's,
//     a sun's orthographic view): each texel's flux lands whole in one cell (1e-4);
//   - rendering: the mean of the rendered `indirect` against the path tracer's `indirect1` (one
//     diffuse bounce, what one LPV pass approximates), printed as the table of
//     docs/variants.md#energy-audit, with bands:
//       * on both scenes every variant but directed's within 0.25-4x of the reference: LPV's
//         two systematic errors, a surface lighting itself (its own VPLs' light read back by it:
//         in a closed room of cells 82% of what standard propagation gives a wall,
//         directed_room_test.cpp) and light lost through open sides and through walls without
//         a GV, pull in opposite directions and neither is a factor 4;
//       * directed propagation, against the standard propagation with the same occlusion (S),
//         at most S under every light (it redirects a surface's own light, flux kept, to the
//         other surfaces, where it is read fewer times) and, on the closed box, at least
//         S - self, self being what each surface gets from its own VPLs in S, measured by runs
//         with every other mesh black (the other surfaces' light is kept). Read literally,
//         alg. 6.3 falls below half of S - self under the point light: this fails on it.
// The reference's mean has a standard error of 0.3-2% (64^2 pixels, 128 paths each).

#include <gtest/gtest.h>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "lpv_support.h"
#include "framework/experiment/experiment.h"
#include "framework/pipeline/light_views.h"
#include "framework/pipeline/pipeline.h"
#include "framework/reference/path_tracer.h"
#include "variants/resources/geometry_volume.h"
#include "backend_comparison.h"
#include "pipeline_test_support.h"

namespace lpvlab {
namespace {

struct AuditScene {
  std::string name;
  bool closed;
  std::vector<std::string> overrides;  // scene and camera
  std::map<std::string, std::string> lights;  // light type -> [[lights]] override
};

const std::vector<AuditScene>& scenes() {
  static const std::vector<AuditScene> s = {
      {"cornell_box",
       true,
       {},
       {{"point", R"(lights=[{name="p",type="point",position=[0.278,0.538,0.279],intensity=1.0}])"},
        {"spot", ""},  // the box's own spot under the ceiling
        // Through the open front, down onto the floor and the back wall.
        {"directional",
         R"(lights=[{name="sun",type="directional",direction=[0.25,-0.45,1.0],intensity=2.0}])"}}},
      {"open_box",
       false,
       // Two cells of margin: the box's walls are two-sided and a sun lights their outsides, whose
       // VPLs, moved one cell out, would lie on the boundary of a grid with one.
       {"scene.file=\"" LPVLAB_SOURCE_DIR "/experiments/scenes/open_box.obj\"", "grid.margin=2.0",
        "camera={position=[0.5,0.75,2.6],look_at=[0.5,0.35,0.5],up=[0.0,1.0,0.0],fov_deg=40.0}"},
       {{"point", R"(lights=[{name="p",type="point",position=[0.5,0.7,0.5],intensity=1.0}])"},
        {"spot",
         R"(lights=[{name="s",type="spot",position=[0.5,0.9,0.5],direction=[0.0,-1.0,0.0],intensity=1.0,outer_cone_deg=50.0,inner_cone_deg=45.0}])"},
        {"directional",
         R"(lights=[{name="sun",type="directional",direction=[0.3,-1.0,-0.4],intensity=2.0}])"}}},
  };
  return s;
}

struct AuditVariant {
  std::string name;
  std::vector<std::string> overrides;
};

const std::vector<AuditVariant>& variants() {
  static const std::vector<AuditVariant> v = {
      {"standard gather", {}},
      {"standard scatter", {"propagation.method=\"scatter\""}},
      {"standard +GV", {"occlusion.type=\"geometry_volume\""}},
      {"standard bounces (+GV)", {"occlusion.type=\"geometry_volume\"", "propagation.bounces=true"}},
      {"SH order 2", {"grid.sh_order=2"}},
      {"SH order 3", {"grid.sh_order=3"}},
      {"directed", {"propagation.type=\"directed\""}},
      {"directed, no dilation", {"propagation.type=\"directed\"", "propagation.dilation=false"}},
      {"directed +GV", {"propagation.type=\"directed\"", "occlusion.type=\"geometry_volume\""}},
      {"directed, read literally", {"propagation.type=\"directed\"", "propagation.release=false"}},
      {"tetrahedral", {"propagation.type=\"tetrahedral\""}},
      {"cascades, 2 levels", {"cascades.levels=2"}},
  };
  return v;
}

constexpr int kSize = 64;
constexpr int kSamples = 128;

std::vector<std::string> common() {
  return {"output.width=" + std::to_string(kSize), "output.height=" + std::to_string(kSize),
          "grid.resolution=24", "propagation.iterations=24", "light_maps.rsm_resolution=128",
          "light_maps.shadow_resolution=512", "timing.warmup=0", "timing.repeats=1",
          "compute.backend=\"cpu\""};
}

std::vector<std::string> overridesFor(const AuditScene& scene, const std::string& light,
                                      const std::vector<std::string>& extra) {
  std::vector<std::string> o = common();
  o.insert(o.end(), scene.overrides.begin(), scene.overrides.end());
  const std::string& l = scene.lights.at(light);
  if (!l.empty()) {
    o.push_back("scene.replace_lights=true");
    o.push_back(l);
  }
  o.insert(o.end(), extra.begin(), extra.end());
  return o;
}

double meanOf(const Image& image) {
  double sum = 0.0;
  for (float v : image.pixels) sum += v;
  return sum / double(image.pixels.size());
}

struct Reference {
  double mean = 0.0, standardError = 0.0;
};

Reference reference(const AuditScene& scene, const std::string& light) {
  Experiment e = loadExperiment("", overridesFor(scene, light, {}));
  const PathTracer tracer(e.scene, e.camera, e.settings.width, e.settings.height, e.reference.tracer);
  Accumulator acc(e.settings.width, e.settings.height);
  tracer.render(acc, kSamples, 0);
  const std::vector<NamedImage> images = acc.images();
  const Image& mean = findAov(images, "indirect1");
  const Image& variance = findAov(images, "indirect1_variance");
  double varianceSum = 0.0;
  for (float v : variance.pixels) varianceSum += v;
  return {meanOf(mean), std::sqrt(varianceSum) / double(variance.pixels.size())};
}

struct AuditRun {
  InjectionBalance injection;
  double indirectMean = 0.0;
};

AuditRun run(const AuditScene& scene, const std::string& light, const AuditVariant& variant) {
  Experiment e = loadExperiment("", overridesFor(scene, light, variant.overrides));
  ShaderCompiler shaders;
  Pipeline pipeline(e.scene, e.camera, e.settings, std::move(e.method), shaders);
  pipeline.renderFrame();
  AuditRun r;
  r.indirectMean = meanOf(findAov(pipeline.readOutputs(), "indirect"));
  r.injection = test::lpvOf(pipeline).measureInjection();
  return r;
}

// What standard propagation gives each surface from its own VPLs, summed over the surfaces
// (meshes), as a mean over the image: a run per mesh with every other mesh black (no VPLs, and
// black pixels: `indirect` is the albedo times what the grid gives), so that its image holds
// only the mesh's own light read back by itself (linear in the light: standard propagation
// without a GV). Physically zero for a flat surface.
// (The GV depends on the geometry alone, so with one the propagation is linear too.)
double ownLightMean(const AuditScene& scene, const std::string& light, const AuditVariant& variant,
                    const std::vector<std::string>& meshes) {
  double sum = 0.0;
  for (const std::string& own : meshes) {
    std::string materials = "materials=[";
    for (const std::string& other : meshes)
      if (other != own) materials += "{mesh=\"" + other + "\",base_color=[0.0,0.0,0.0]},";
    materials.back() = ']';
    AuditVariant isolated = variant;
    isolated.overrides.push_back(materials);
    sum += run(scene, light, isolated).indirectMean;
  }
  return sum;
}

// Each directed variant and the standard propagation it is built on (the same occlusion).
const std::map<std::string, std::string>& standardOf() {
  static const std::map<std::string, std::string> m = {{"directed", "standard gather"},
                                                       {"directed, no dilation", "standard gather"},
                                                       {"directed +GV", "standard +GV"}};
  return m;
}

class EnergyAudit : public ::testing::TestWithParam<int> {};  // the scene

TEST_P(EnergyAudit, InjectionKeepsTheRsmFluxAndEveryVariantStaysInItsBand) {
  test::glTestContext();
  const AuditScene& scene = scenes().at(GetParam());
  std::ostringstream table;
  table << std::setprecision(3);
  table << "\n| " << scene.name << " | point | spot | directional |\n|---|---:|---:|---:|\n";
  std::map<std::string, Reference> references;
  for (const std::string light : {"point", "spot", "directional"})
    references[light] = reference(scene, light);
  table << "| reference `indirect1` mean (standard error) |";
  for (const std::string light : {"point", "spot", "directional"})
    table << " " << references[light].mean << " (" << references[light].standardError << ") |";
  table << "\n";

  std::map<std::string, std::map<std::string, double>> ratio;  // variant -> light -> mean / ref
  for (const AuditVariant& variant : variants()) {
    table << "| " << variant.name << " |";
    for (const std::string light : {"point", "spot", "directional"}) {
      SCOPED_TRACE(scene.name + ", " + light + " light, " + variant.name);
      const AuditRun r = run(scene, light, variant);
      const Reference& ref = references[light];
      ASSERT_GT(ref.mean, 10.0 * ref.standardError) << "the reference is lit";
      // Injection: the grid holds the RSM's reflected flux (every view of every light type).
      EXPECT_GT(r.injection.rsmFlux, 0.0);
      EXPECT_NEAR(r.injection.gridFlux, r.injection.rsmFlux, 1e-4 * r.injection.rsmFlux);
      ASSERT_TRUE(std::isfinite(r.indirectMean));
      EXPECT_GT(r.indirectMean, 0.0);
      ratio[variant.name][light] = r.indirectMean / ref.mean;
      table << " " << ratio[variant.name][light] << " |";
    }
    table << "\n";
  }
  // variant -> light -> the variant's light from each surface's own VPLs, over the reference
  std::map<std::string, std::map<std::string, double>> ownLight;
  if (scene.closed)
    for (const AuditVariant& variant : variants()) {
      if (variant.name != "standard gather" && variant.name != "standard +GV") continue;
      table << "| " << variant.name << ": each surface's own light |";
      for (const std::string light : {"point", "spot", "directional"}) {
        ownLight[variant.name][light] =
            ownLightMean(scene, light, variant,
                         {"floor", "ceiling", "back wall", "right wall", "left wall", "short block",
                          "tall block"}) /
            references[light].mean;
        table << " " << ownLight[variant.name][light] << " |";
      }
      table << "\n";
    }
  std::cout << "[ energy audit ] rendered `indirect` mean / reference `indirect1` mean, CPU "
               "backend, 64^2, 24^3 grid, 24 iterations:"
            << table.str();

  for (const std::string light : {"point", "spot", "directional"}) {
    SCOPED_TRACE(scene.name + ", " + light + " light");
    for (const auto& [directed, standardName] : standardOf()) {
      // At most the standard propagation it is built on: a surface's own light is redirected to
      // the others, where it is read fewer times.
      const double standard = ratio[standardName][light];
      EXPECT_LE(ratio[directed][light], standard * (1.0 + 1e-6)) << directed;
      // At least what standard propagation carries from one surface to another.
      if (scene.closed) {
        EXPECT_GE(ratio[directed][light], standard - ownLight[standardName][light]) << directed;
      }
    }
    for (const AuditVariant& variant : variants()) {
      // Directed propagation's bands are the ones above, relative to standard propagation with
      // the same occlusion; read literally it is issue 42's failure, kept as a row of the table.
      if (variant.name.starts_with("directed")) continue;
      EXPECT_GT(ratio[variant.name][light], 0.25) << variant.name;
      EXPECT_LT(ratio[variant.name][light], 4.0) << variant.name;
    }
  }
  if (scene.closed) {  // under the point light, where every surface sends VPLs (issue 42)
    EXPECT_LT(ratio["directed, read literally"]["point"],
              0.5 * (ratio["standard gather"]["point"] - ownLight["standard gather"]["point"]))
        << "alg. 6.3 read literally loses the light between surfaces";
  }
}

// Issue 42's candidate causes of directed propagation's lost light, checked under each light type
// (none of them was the cause: docs/variants/directed.md#directed): the RSM's normals are world-space
// unit normals facing their light in every view (a point light's six cube faces, the faces a
// spot's cone reaches, a sun's one view), and the normal grid directed propagation reads holds every view's VPLs: its flux
// weights sum to the RSM's flux and its flux-weighted normals to the RSM's.
TEST(EnergyAuditInjection, RsmNormalsFaceTheirLightInEveryViewAndTheNormalGridHoldsThemAll) {
  test::glTestContext();
  const AuditScene& scene = scenes().at(0);
  for (const std::string light : {"point", "spot", "directional"}) {
    SCOPED_TRACE(light + " light");
    Experiment e = loadExperiment("", overridesFor(scene, light, {"propagation.type=\"directed\""}));
    ShaderCompiler shaders;
    Pipeline pipeline(e.scene, e.camera, e.settings, std::move(e.method), shaders);
    pipeline.renderFrame();
    const LightMaps& maps = pipeline.lightMaps();
    const std::size_t texels = std::size_t(maps.rsmResolution) * maps.rsmResolution;
    auto read = [&](const gl::Texture& t) {
      std::vector<float> v(texels * maps.views * 4);
      glGetTextureImage(t.id(), 0, GL_RGBA, GL_FLOAT, GLsizei(v.size() * sizeof(float)), v.data());
      return v;
    };
    const std::vector<float> position = read(maps.rsmPosition), normal = read(maps.rsmNormal),
                             flux = read(maps.rsmFlux);
    glm::dvec4 rsm(0.0);  // sum of Phi n, sum of Phi (Phi over RGB)
    int facingAway = 0, notUnit = 0, viewsWithFlux = 0;
    for (int view = 0; view < maps.views; ++view) {
      const GpuLight& l = maps.records.lights.at(int(maps.records.views.at(view).params.z));
      bool lit = false;
      for (std::size_t t = 0; t < texels; ++t) {
        const std::size_t i = 4 * (std::size_t(view) * texels + t);
        const double phi = double(flux[i]) + flux[i + 1] + flux[i + 2];
        if (phi <= 0.0) continue;
        lit = true;
        const glm::dvec3 n(normal[i], normal[i + 1], normal[i + 2]);
        const glm::dvec3 x(position[i], position[i + 1], position[i + 2]);
        const glm::dvec3 towardsLight = light == "directional" ? -glm::dvec3(l.directionCosOuter)
                                                               : glm::dvec3(l.positionType) - x;
        notUnit += std::abs(glm::length(n) - 1.0) > 1e-3;
        facingAway += glm::dot(n, towardsLight) <= 0.0;
        rsm += glm::dvec4(phi * n, phi);
      }
      viewsWithFlux += lit;
    }
    std::vector<float> stored(std::size_t(4) * test::lpvOf(pipeline).levels().front().geometry.cellCount());
    test::lpvOf(pipeline).resources().get(kNormalGrid).normals.download(stored.data(), stored.size() * sizeof(float));
    glm::dvec4 grid(0.0);
    for (std::size_t i = 0; i < stored.size(); i += 4)
      grid += glm::dvec4(stored[i], stored[i + 1], stored[i + 2], stored[i + 3]);
    std::cout << "[ energy audit ] " << light << " light: " << viewsWithFlux << " of " << maps.views
              << " views lit; RSM sum Phi n = (" << rsm.x << ", " << rsm.y << ", " << rsm.z
              << "), sum Phi " << rsm.w << "; normal grid (" << grid.x << ", " << grid.y << ", "
              << grid.z << "), " << grid.w << "\n";
    EXPECT_EQ(notUnit, 0);
    EXPECT_EQ(facingAway, 0) << "RSM normals facing away from their light: not world space";
    EXPECT_EQ(viewsWithFlux, maps.views) << "every view of the light sees lit surfaces";
    if (light == "point") {
      EXPECT_EQ(maps.views, 6);
    }
    EXPECT_GT(rsm.w, 0.0);
    for (int k = 0; k < 4; ++k) EXPECT_NEAR(grid[k], rsm[k], 1e-4 * rsm.w) << "component " << k;
  }
}

// The variants whose kernels differ most from standard propagation's (directed's release and
// reprojection, the tetrahedral lattice, the cascades' levels) give the same indirect light on
// both backends under every light type on the closed box (their kernel tests, on hand-made
// grids, know no lights).
TEST(EnergyAuditBackends, DirectedTetrahedralAndCascadesAgreeOnBothBackendsUnderEveryLight) {
  test::glTestContext();
  const AuditScene& scene = scenes().at(0);
  for (const std::string variantName : {"directed", "directed +GV", "tetrahedral", "cascades, 2 levels"})
    for (const std::string light : {"point", "spot", "directional"}) {
      const std::string what = variantName + ", " + light + " light";
      AuditVariant variant;
      for (const AuditVariant& v : variants())
        if (v.name == variantName) variant = v;
      std::map<std::string, Image> indirect;
      for (const std::string backend : {"cpu", "gl"}) {
        std::vector<std::string> o = overridesFor(scene, light, variant.overrides);
        o.push_back("compute.backend=\"" + backend + "\"");  // after common()'s, so it wins
        Experiment e = loadExperiment("", o);
        ShaderCompiler shaders;
        Pipeline pipeline(e.scene, e.camera, e.settings, std::move(e.method), shaders);
        pipeline.renderFrame();
        indirect[backend] = findAov(pipeline.readOutputs(), "indirect");
      }
      const test::ImageDifference d = test::difference(indirect["cpu"], indirect["gl"]);
      std::cout << "[ energy audit ] " << what << ": CPU against GL, largest difference "
                << d.largest / d.scale << " of the image's largest value\n";
      test::expectSameImage(indirect["cpu"], indirect["gl"], what);
    }
}

INSTANTIATE_TEST_SUITE_P(Scenes, EnergyAudit, ::testing::Values(0, 1),
                         [](const auto& info) { return scenes().at(info.param).name; });

}  // namespace
}  // namespace lpvlab
