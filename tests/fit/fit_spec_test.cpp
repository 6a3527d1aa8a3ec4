// The [fit] table: every bad input is an Error naming the file, the key and the problem; and
// `include` (how a fit's fitted.toml is used) merges over `extends` and under the file's keys.

#include <gtest/gtest.h>

#include "error_support.h"
#include "fit/fit_test_support.h"
#include "framework/experiment/experiment.h"
#include "framework/fit/fit_output.h"
#include "framework/fit/fit_spec.h"

namespace lpvlab {
namespace {

std::string fitFile(const std::string& fit) {
  return test::smallCornellBox() + "[fit]\n" + fit;
}

const std::string kViews = "[[fit.views]]\nname = \"main\"\n";

TEST(FitSpec, ReadsParametersViewsAndDefaults) {
  test::FitFiles files("spec");
  const std::string path = files.write(
      "a.toml", fitFile("parameters = [{ key = \"propagation.damping\", lower = 0.5, upper = 1.5 },\n"
                        "              { key = \"injection.shift\", initial = 0.8 }]\n"
                        "residual = \"relative\"\nloss = \"huber\"\nloss_scale = 0.5\n" + kViews +
                        "[[fit.held_out]]\nname = \"side\"\ncamera = { position = [0.5, 0.3, -0.6], "
                        "look_at = [0.28, 0.27, 0.28] }\n"));
  const FitSpec spec = readFitSpec(path);
  ASSERT_EQ(spec.parameters.size(), 2u);
  EXPECT_EQ(spec.parameters[0].key, "propagation.damping");
  EXPECT_EQ(spec.parameters[0].initial, 1.0);  // the strategy's default
  EXPECT_EQ(spec.parameters[0].lower, 0.5);
  EXPECT_EQ(spec.parameters[1].initial, 0.8);
  EXPECT_EQ(spec.residual, ResidualKind::Relative);
  EXPECT_EQ(spec.loss, LossKind::Huber);
  ASSERT_EQ(spec.views.size(), 1u);
  ASSERT_EQ(spec.heldOut.size(), 1u);
  const toml::table side = spec.viewTable(spec.heldOut[0]);
  EXPECT_TRUE(side.at_path("camera.position").is_array());
  EXPECT_EQ(side.at_path("grid.resolution").value_or(0), 16);
  EXPECT_FALSE(side.contains("fit"));
}

TEST(FitSpec, BadFilesGiveClearErrors) {
  test::FitFiles files("errors");
  auto errorFor = [&](const std::string& fit) {
    const std::string path = files.write("bad.toml", fitFile(fit));
    return test::errorOf([&] { readFitSpec(path); });
  };
  std::string e = errorFor("parameters = [{ key = \"propagation.dampening\" }]\n" + kViews);
  EXPECT_TRUE(test::contains(e, "bad.toml"));
  EXPECT_TRUE(test::contains(e, "unknown parameter 'propagation.dampening'"));
  EXPECT_TRUE(test::contains(e, "propagation.damping"));  // the valid ones are listed
  e = errorFor("parameters = [{ key = \"propagation.iterations\" }]\n" + kViews);
  EXPECT_TRUE(test::contains(e, "'propagation.iterations'"));
  EXPECT_TRUE(test::contains(e, "not real-valued"));
  e = errorFor("parameters = [{ key = \"grid.margin\" }]\n" + kViews);
  EXPECT_TRUE(test::contains(e, "not a strategy parameter"));
  e = errorFor("parameters = [{ key = \"propagation.damping\", initial = 2.0, lower = 0.5, upper = 1.5 }]\n" + kViews);
  EXPECT_TRUE(test::contains(e, "fit.parameters[0].initial"));
  EXPECT_TRUE(test::contains(e, "exclude its initial value 2"));
  e = errorFor("parameters = [{ key = \"propagation.damping\", lower = 1.5, upper = 0.5 }]\n" + kViews);
  EXPECT_TRUE(test::contains(e, "bounds of 'propagation.damping' are empty"));
  e = errorFor("parameters = [{ key = \"propagation.damping\" }]\n");
  EXPECT_TRUE(test::contains(e, "key 'fit.views': no views to fit on"));
  e = errorFor("parameters = []\n" + kViews);
  EXPECT_TRUE(test::contains(e, "no parameters to fit"));
  e = errorFor("parameters = [{ key = \"propagation.damping\" }]\nresiduals = \"log\"\n" + kViews);
  EXPECT_TRUE(test::contains(e, "unknown key 'fit.residuals'"));
  e = errorFor("parameters = [{ key = \"propagation.damping\" }]\nloss = \"tukey\"\n" + kViews);
  EXPECT_TRUE(test::contains(e, "fit.loss"));
  e = errorFor("parameters = [{ key = \"propagation.damping\" }]\n[[fit.views]]\ncamera = {}\n");
  EXPECT_TRUE(test::contains(e, "fit.views[0].name': every view needs a name"));
  const std::string noFit = files.write("nofit.toml", test::smallCornellBox());
  EXPECT_TRUE(test::contains(test::errorOf([&] { readFitSpec(noFit); }), "no [fit] table"));
}

TEST(FitSpec, RunningAFitFileRunsItsBaseExperiment) {
  test::FitFiles files("base");
  const std::string path = files.write(
      "a.toml", fitFile("parameters = [{ key = \"propagation.damping\" }]\n" + kViews));
  EXPECT_EQ(loadExperiment(path).settings.width, 64);
}

TEST(Include, MergesOverExtendsAndUnderTheFilesOwnKeys) {
  test::FitFiles files("include");
  files.write("base.toml", "[propagation]\ndamping = 0.5\niterations = 4\n[injection]\nshift = 0.25\n");
  files.write("p.toml", "[propagation]\ndamping = 0.7\niterations = 5\n");
  files.write("q.toml", "[propagation]\niterations = 6\n");
  const std::string main = files.write(
      "main.toml", "extends = \"base.toml\"\ninclude = [\"p.toml\", \"q.toml\"]\n"
                   "[injection]\nshift = 1.5\n");
  const nlohmann::json c = loadExperiment(main).configuration;
  EXPECT_EQ(c["propagation"]["damping"].get<double>(), 0.7);  // include over extends
  EXPECT_EQ(c["propagation"]["iterations"].get<int>(), 6);    // later include over earlier
  EXPECT_EQ(c["injection"]["shift"].get<double>(), 1.5);      // the file's own keys win
  const std::string own = files.write(
      "own.toml", "include = [\"p.toml\"]\n[propagation]\ndamping = 0.9\n");
  EXPECT_EQ(loadExperiment(own).configuration["propagation"]["damping"].get<double>(), 0.9);
  const std::string missing = files.write("missing.toml", "include = [\"nope.toml\"]\n");
  EXPECT_TRUE(test::contains(test::errorOf([&] { loadExperiment(missing); }),
                             "missing.toml: key 'include': file"));
  const std::string wrongType = files.write("wrong.toml", "include = \"p.toml\"\n");
  EXPECT_TRUE(test::contains(test::errorOf([&] { loadExperiment(wrongType); }), "expected a list"));
  const std::string cycle = files.write("cycle.toml", "include = [\"cycle.toml\"]\n");
  EXPECT_TRUE(test::contains(test::errorOf([&] { loadExperiment(cycle); }), "cycle"));
}

TEST(FittedToml, IsOneIncludeAwayFromAnExperiment) {
  test::FitFiles files("fitted");
  const std::string path = files.write(
      "a.toml", fitFile("parameters = [{ key = \"propagation.damping\" }, "
                        "{ key = \"injection.shift\" }, { key = \"propagation.far_face_solid_angle\" }]\n" + kViews));
  const FitSpec spec = readFitSpec(path);
  FitResult result;
  result.values = {1.0 / 3.0, 1.25, 0.5};
  result.stdDev = {0.01, 0.02, NAN};
  result.sandwichStdDev = {0.03, 0.05, NAN};
  result.undetermined = {false, false, true};
  result.atBound = {false, true, false};
  files.write("fitted.toml", fittedToml(spec, result));
  const std::string user = files.write("user.toml", "include = [\"fitted.toml\"]\n");
  const nlohmann::json c = loadExperiment(user).configuration;
  EXPECT_EQ(c["propagation"]["damping"].get<double>(), 1.0 / 3.0);  // exactly: 17 digits
  EXPECT_EQ(c["injection"]["shift"].get<double>(), 1.25);
  // The undetermined parameter is left out: the experiment keeps its default.
  EXPECT_NEAR(c["propagation"]["far_face_solid_angle"].get<double>(), 0.40066968, 1e-8);
}

// fit.md: per parameter the verdict from z = (fitted - published) / the larger deviation, the
// undetermined said so; per view, grouped, the error before and after and the gain.
TEST(FitReport, StatesVerdictsAndGains) {
  test::FitFiles files("report");
  const std::string path = files.write(
      "a.toml", fitFile("parameters = [{ key = \"propagation.damping\" }, "
                        "{ key = \"injection.shift\" }, { key = \"propagation.far_face_solid_angle\" }]\n" +
                        kViews + "[[fit.held_out]]\nname = \"other\"\n"));
  const FitSpec spec = readFitSpec(path);
  FitResult result;
  result.values = {0.9, 1.05, 0.5};
  // damping: z = -0.1 / max(0.01, 0.02) = -5; shift: 0.05 / max(0.02, 0.01) = 2.5.
  result.stdDev = {0.01, 0.02, NAN};
  result.sandwichStdDev = {0.02, 0.01, NAN};
  result.undetermined = {false, false, true};
  result.atBound = {false, false, false};
  const auto errors = [](double mainRmse, double otherRmse) {
    const auto view = [](const char* name, bool heldOut, double rmse) {
      return nlohmann::json{{"view", name}, {"held_out", heldOut}, {"cost", 0.0},
                            {"metrics", {{"rmse", rmse}, {"rel_mse", 0.1}, {"flip", 0.5}}}};
    };
    return nlohmann::json::array({view("main", false, mainRmse), view("other", true, otherRmse)});
  };
  const std::string report = fitReport(spec, result, errors(0.04, 0.02), errors(0.02, 0.03));
  const auto line = [&](const std::string& start) {
    const auto at = report.find(start);
    return at == std::string::npos ? std::string() : report.substr(at, report.find('\n', at) - at);
  };
  EXPECT_TRUE(test::contains(line("| `propagation.damping`"), "| -5.00 | differs significantly")) << report;
  EXPECT_TRUE(test::contains(line("| `injection.shift`"), "| 2.50 | not significantly different")) << report;
  EXPECT_TRUE(test::contains(line("| `propagation.far_face_solid_angle`"), "undetermined")) << report;
  EXPECT_TRUE(test::contains(line("| main"), "| 0.04 | 0.02 | +50.0%")) << report;
  EXPECT_TRUE(test::contains(line("| other"), "| 0.02 | 0.03 | -50.0%")) << report;
  EXPECT_LT(report.find("### Fitted views"), report.find("| main"));
  EXPECT_LT(report.find("### Held-out views"), report.find("| other"));
  EXPECT_GT(report.find("### Held-out views"), report.find("| main"));
}

}  // namespace
}  // namespace lpvlab
