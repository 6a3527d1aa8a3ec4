// Radiosity through the pipeline on the OBJ Cornell box (lit only by its emissive ceiling quad)
// against the path tracer's `indirect` and `indirect1`: the error falls as patches shrink. Also
// what later frames recompute, and the method's errors.
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "framework/core/error.h"
#include "method_test_support.h"

namespace lpvlab {
namespace {

constexpr int kSize = 64;
const std::string kObjCornell = std::string(LPVLAB_SOURCE_DIR) + "/experiments/cornell_box_obj_reference.toml";

std::vector<std::string> sized(std::vector<std::string> overrides) {
  overrides.push_back("output.width=" + std::to_string(kSize));
  overrides.push_back("output.height=" + std::to_string(kSize));
  return overrides;
}

// The reference of the OBJ Cornell box at the test's size, once per binary.
const std::vector<NamedImage>& objCornellReference() {
  static const std::vector<NamedImage> images = [] {
    const Experiment e = loadExperiment(kObjCornell, sized({}));
    TracerSettings settings;
    settings.seed = 3;
    const PathTracer tracer(e.scene, e.camera, kSize, kSize, settings);
    Accumulator acc(kSize, kSize);
    tracer.render(acc, 1024, 0);
    return acc.images();
  }();
  return images;
}

struct Frames {
  std::vector<NamedImage> aovs;
  nlohmann::json statistics;
  std::vector<FrameTimes> times;
  std::vector<std::map<std::string, std::vector<WorkCount>>> work;
};

// `frames` frames of the OBJ Cornell box with `overrides`; `between` runs before every frame
// after the first.
Frames runObjCornell(const std::vector<std::string>& overrides, int frames = 1,
                     const std::function<void(Pipeline&)>& between = nullptr) {
  test::glTestContext();
  Experiment e = loadExperiment(kObjCornell, sized(overrides));
  ShaderCompiler shaders;
  Pipeline pipeline(e.scene, e.camera, e.settings, std::move(e.method), shaders);
  Frames out;
  for (int f = 0; f < frames; ++f) {
    if (f > 0 && between) between(pipeline);
    out.times.push_back(pipeline.renderFrame());
    out.work.push_back(pipeline.method().work());
  }
  out.aovs = pipeline.readOutputs();
  out.statistics = pipeline.method().statistics();
  return out;
}

// Pixels whose 3x3 neighbourhood is one flat surface of one material: test::awayFromEdges, and
// the same albedo throughout. (The OBJ box's light hangs 1 cm below the ceiling, facing the same
// way: pixels at its edge look through the slit into the bright gap above it, a sub-pixel
// feature that a G-buffer samples at the pixel's centre and the path tracer over its area.)
std::vector<bool> flatOneMaterial(const std::vector<NamedImage>& aovs) {
  std::vector<bool> keep = test::awayFromEdges(aovs);
  const Image& albedo = findAov(aovs, "albedo");
  for (int y = 1; y + 1 < albedo.height; ++y)
    for (int x = 1; x + 1 < albedo.width; ++x)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx)
          for (int c = 0; c < 3; ++c)
            if (std::abs(albedo.at(x + dx, y + dy, c) - albedo.at(x, y, c)) > 1e-3f)
              keep[std::size_t(y) * albedo.width + x] = false;
  return keep;
}

// Relative L1 error over the pixels away from edges: sum |a - b| / sum b, RGB.
double relativeError(const Image& a, const Image& b, const std::vector<bool>& keep) {
  double difference = 0.0, total = 0.0;
  for (std::size_t p = 0; p < keep.size(); ++p)
    for (int c = 0; c < 3 && keep[p]; ++c) {
      difference += std::abs(double(a.pixels[p * 3 + c]) - b.pixels[p * 3 + c]);
      total += b.pixels[p * 3 + c];
    }
  return difference / total;
}

// The part of that error the reference's own noise makes: E|N(0, var)| = sqrt(2 var / pi).
double referenceNoise(const Image& reference, const Image& variance, const std::vector<bool>& keep) {
  double noise = 0.0, total = 0.0;
  for (std::size_t p = 0; p < keep.size(); ++p)
    for (int c = 0; c < 3 && keep[p]; ++c) {
      noise += std::sqrt(2.0 * std::max(0.0f, variance.pixels[p * 3 + c]) / M_PI);
      total += reference.pixels[p * 3 + c];
    }
  return noise / total;
}

// The ratio of the image means over the kept pixels.
double ratioOfMeans(const Image& a, const Image& b, const std::vector<bool>& keep) {
  double sa = 0.0, sb = 0.0;
  for (std::size_t p = 0; p < keep.size(); ++p)
    for (int c = 0; c < 3 && keep[p]; ++c) sa += a.pixels[p * 3 + c], sb += b.pixels[p * 3 + c];
  return sa / sb;
}

// Against the path tracer's `aov` (`indirect`, or `indirect1` in one-bounce mode), with ray-cast
// form factors (the hemicube's own tests are radiosity_hemicube_test.cpp): uniform patches of
// 0.5 and 0.25 m, then 0.25 m refined adaptively by 2 and 4 levels. The light hangs 1 cm below
// the ceiling and both its sides emit: the gap above it traps light, and a uniform patch that
// straddles the light's outline spreads the gap's radiosity over the room's side of the ceiling,
// so uniform patches converge slowly and adaptive subdivision, which splits exactly those, fast.
void errorFallsAsPatchesShrink(const std::string& aov, bool oneBounce) {
  const Image& reference = findAov(objCornellReference(), aov);
  const Image& variance = findAov(objCornellReference(), aov + "_variance");
  const std::vector<std::vector<std::string>> settings = {
      {"indirect.patch_size=0.5"},
      {"indirect.patch_size=0.25"},
      {"indirect.patch_size=0.25", "indirect.adaptive_levels=2"},
      {"indirect.patch_size=0.25", "indirect.adaptive_levels=4"}};
  std::vector<double> errors, ratios;
  std::vector<bool> keep;
  for (const std::vector<std::string>& extra : settings) {
    std::vector<std::string> o = {"indirect.method=radiosity", "indirect.form_factors=rays", "indirect.rays=1024",
                                  std::string("indirect.one_bounce=") + (oneBounce ? "true" : "false")};
    o.insert(o.end(), extra.begin(), extra.end());
    const Frames run = runObjCornell(o);
    if (keep.empty()) keep = flatOneMaterial(run.aovs);
    errors.push_back(relativeError(findAov(run.aovs, "indirect"), reference, keep));
    ratios.push_back(ratioOfMeans(findAov(run.aovs, "indirect"), reference, keep));
    EXPECT_TRUE(run.statistics["solver"]["converged"].get<bool>());
  }
  const double noise = referenceNoise(reference, variance, keep);
  std::printf("%s: relative L1 error (ratio of means) at 0.5 m, 0.25 m, 0.25 m + 2 and + 4 adaptive levels: "
              "%.3f (%.3f) %.3f (%.3f) %.3f (%.3f) %.3f (%.3f); the reference's own noise %.3f\n",
              aov.c_str(), errors[0], ratios[0], errors[1], ratios[1], errors[2], ratios[2], errors[3], ratios[3],
              noise);
  for (std::size_t k = 1; k < errors.size(); ++k) EXPECT_LT(errors[k], errors[k - 1]) << k;
  // Stated: at 4 adaptive levels, the error beyond the reference's own noise is below 12%, and
  // the mean within 5%.
  EXPECT_LT(errors[3] - noise, 0.12);
  EXPECT_NEAR(ratios[3], 1.0, 0.05);
}

TEST(Radiosity, ObjCornellBoxIndirectApproachesThePathTracerAsPatchesShrink) {
  errorFallsAsPatchesShrink("indirect", false);
}

TEST(Radiosity, OneBounceModeApproachesTheOneBounceReference) { errorFallsAsPatchesShrink("indirect1", true); }

TEST(Radiosity, LaterFramesRedoOnlyWhatChanged) {
  // Frame 2: nothing moved: no meshing, form factors, first shot or solve; only the display.
  const Frames run = runObjCornell({"indirect.method=radiosity", "indirect.patch_size=0.5"}, 2);
  auto count = [&](int frame, const std::string& stage) { return run.work[std::size_t(frame)].at(stage).at(0).units; };
  EXPECT_GT(count(0, "meshing"), 0.0);
  EXPECT_GT(count(0, "form_factors"), 0.0);
  EXPECT_GT(count(0, "solve"), 0.0);
  EXPECT_EQ(count(1, "meshing"), 0.0);
  EXPECT_EQ(count(1, "form_factors"), 0.0);
  EXPECT_EQ(count(1, "solve"), 0.0);
  EXPECT_GT(count(1, "indirect"), 0.0);
}

TEST(Radiosity, SolversAndEstimatorsAgreeOnTheImage) {
  // On the built-in Cornell box (its point light: no trap). Gauss-Seidel and Jacobi solve one
  // system: the same image. Shooting solves the reciprocal one (F_ji = A_i F_ij / A_j from the
  // shooters' rows), and rays estimate the same form factors as the hemicube (from the whole patch
  // rather than its centroid): images within a few per cent.
  const std::vector<std::string> base = {"indirect.method=radiosity", "indirect.patch_size=0.1",
                                         "indirect.tolerance=1e-7", "output.width=64", "output.height=64"};
  auto with = [&](std::vector<std::string> extra) {
    std::vector<std::string> o = base;
    o.insert(o.end(), extra.begin(), extra.end());
    return test::runMethod(o);
  };
  const test::MethodRun gs = with({"indirect.solver=gauss_seidel"});
  const test::MethodRun jacobi = with({"indirect.solver=jacobi"});
  const test::MethodRun shooting = with({"indirect.solver=shooting"});
  const test::MethodRun rays = with({"indirect.form_factors=rays", "indirect.rays=4096"});
  const std::vector<bool> keep = flatOneMaterial(gs.aovs);
  const Image& reference = gs.indirect();
  EXPECT_LT(relativeError(jacobi.indirect(), reference, keep), 1e-5);
  const double shootingError = relativeError(shooting.indirect(), reference, keep);
  const double raysError = relativeError(rays.indirect(), reference, keep);
  std::printf("shooting vs gathering %.4f, rays vs hemicube %.4f (reciprocity error of the hemicube rows %.4f)\n",
              shootingError, raysError, gs.statistics["form_factors"]["reciprocity_error"].get<double>());
  EXPECT_LT(shootingError, 0.03);
  EXPECT_LT(raysError, 0.05);
  const nlohmann::json energy = shooting.statistics["solver"]["energy_W"];
  EXPECT_NEAR(energy["absorbed"].get<double>() + energy["escaped"].get<double>() + energy["unshot"].get<double>(),
              energy["first_shot"].get<double>(), 1e-9 * energy["first_shot"].get<double>());
}

TEST(Radiosity, BadParametersAreNamedErrors) {
  const std::vector<std::pair<std::string, std::string>> bad = {
      {"indirect.hemicube_resolution=63", "hemicube_resolution"},
      {"indirect.solver=conjugate_gradient", "solver"},
      {"indirect.patch_size=-1", "patch_size"},
      {"indirect.max_shots=10", "max_shots"},  // a shooting key without shooting
      {"indirect.rays=64", "rays"},            // a ray key with the hemicube
  };
  for (const auto& [override, key] : bad) {
    try {
      runObjCornell({"indirect.method=radiosity", override});
      ADD_FAILURE() << override << ": no error";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << override << ": " << e.what();
    }
  }
  // Too many patches: an error that says which knob to turn.
  try {
    runObjCornell({"indirect.method=radiosity", "indirect.patch_size=0.001", "indirect.max_patches=1000"});
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("max_patches"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace lpvlab
