// `lpvlab list --json`: the same catalogue as `lpvlab list`, for programs. Every strategy the text
// lists is in it with its stage, resources, CPU kernel and parameters' defaults (standard
// propagation's 32 iterations, the directed release's region angle); every method with its own
// stages in the order it runs them; LPV's stages in the pipeline's order.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <set>
#include <string>

#include "executable_support.h"
#include "io/temp_dir.h"

namespace lpvlab {
namespace {

TEST(ListJson, IsTheTextListsCatalogueWithDefaultsStagesAndResources) {
  test::TempDir dir;
  const test::LpvlabResult text = test::runLpvlab("list", dir.path(), dir.path());
  const test::LpvlabResult json = test::runLpvlab("list --json", dir.path(), dir.path());
  ASSERT_EQ(text.exitCode, 0) << text.err;
  ASSERT_EQ(json.exitCode, 0) << json.err;
  const nlohmann::json list = nlohmann::json::parse(json.out);

  std::set<std::string> named;
  for (const nlohmann::json& s : list.at("strategies")) {
    named.insert(s.at("stage").get<std::string>() + "/" + s.at("name").get<std::string>());
    EXPECT_NE(text.out.find("  " + s.at("name").get<std::string>() + ": "), std::string::npos)
        << s.at("name") << " is in the text list";
    EXPECT_TRUE(s.at("parameters").is_object());
    EXPECT_TRUE(s.at("resources").contains("produces"));
  }
  EXPECT_TRUE(named.count("propagation/standard") && named.count("propagation/directed") &&
              named.count("occlusion/geometry_volume") && named.count("rendering/trilinear"));
  for (const nlohmann::json& s : list.at("strategies")) {
    if (s.at("name") == "standard") {
      EXPECT_EQ(s.at("parameters").at("iterations"), 32);
    }
    if (s.at("name") == "directed") {
      EXPECT_EQ(s.at("parameters").at("region_angle_deg"), 10);
    }
    if (s.at("name") == "geometry_volume") {
      EXPECT_NE(s.at("resources").at("produces").dump().find("geometry_volume"), std::string::npos);
    }
    // Whether a run without GL can use it (no CPU kernel missing, nothing drawn with GL).
    EXPECT_EQ(s.at("without_gl"), s.at("name") != "sky_columns" && s.at("name") != "subsurface") << s.dump();
  }
  bool radiosity = false, lpv = false;
  for (const nlohmann::json& m : list.at("methods")) {
    if (m.at("name") == "lpv") {
      lpv = true;
      EXPECT_EQ(m.at("stages").front(), "clear");
      EXPECT_EQ(m.at("stages").back(), "indirect");
      // The default composition injects RSM texels, so it consumes the RSMs, and a summary shows
      // its strategies.
      EXPECT_EQ(m.at("consumes"), nlohmann::json({"rsm"}));
      EXPECT_NE(m.at("summary_keys").dump().find("propagation.type"), std::string::npos);
    }
    if (m.at("name") == "instant_radiosity") {
      EXPECT_EQ(m.at("consumes"), nlohmann::json::array()) << "it makes its own VPLs";
    }
    if (m.at("name") == "radiosity") {
      radiosity = true;
      EXPECT_EQ(m.at("stages").front(), "meshing");
      EXPECT_EQ(m.at("stages").back(), "indirect");
      EXPECT_EQ(m.at("parameters").at("form_factors"), "hemicube");
    }
  }
  EXPECT_TRUE(radiosity);
  EXPECT_TRUE(lpv);  // LPV is one registered method among the others
  EXPECT_EQ(list.at("pipeline_stages").front(), "shadow_maps");
  EXPECT_EQ(list.at("pipeline_stages").back(), "direct");
}

}  // namespace
}  // namespace lpvlab
