// The resource contract (framework/pipeline/named_resources.h, composition.h):
//   a. a consumed resource nobody produces is refused, naming the consumer, the resource and the
//      registered strategies that would produce it: directed propagation without the RSM
//      injection, a sky without sky injection, and a resource no registered strategy knows;
//   b. a resource exists only when it is produced and used: produced alone, or read alone, it is
//      not allocated (and reading what nobody produces is no error);
//   c. the pipeline allocates a resource the framework has never heard of (a test's own type),
//      once per cascade level with that level's placement, clears it before every frame, and
//      hands each level's to its consumer;
//   d. prepare() sees the scene, its light views and the image size;
//   e. a table's resource asked for under another type, or missing, is an Error naming it.

#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <toml++/toml.h>

#include "error_support.h"
#include "lpv_support.h"
#include "framework/core/parameters.h"
#include "framework/experiment/experiment.h"
#include "framework/pipeline/composition.h"
#include "framework/pipeline/pipeline.h"
#include "framework/pipeline/scene_gpu.h"
#include "variants/resources/geometry_volume.h"
#include "variants/resources/sky_light.h"
#include "pipeline_test_support.h"

namespace lpvlab {
namespace {

template <class Interface>
std::unique_ptr<Interface> createDefault(const std::string& type) {
  static const toml::table empty;
  Params params(empty, "resource contract test");
  auto strategy = Registry<Interface>::instance().create(params, type);
  params.finish();
  return strategy;
}

Strategies composition(const std::string& injection, const std::string& occlusion,
                       const std::string& propagation) {
  Strategies strategies;
  strategies.injection.push_back(createDefault<InjectionStrategy>(injection));
  strategies.occlusion = createDefault<OcclusionStrategy>(occlusion);
  strategies.propagation = createDefault<PropagationStrategy>(propagation);
  strategies.rendering.push_back(createDefault<RenderingStrategy>("trilinear"));
  return strategies;
}

// ---- a. refusals ------------------------------------------------------------------------------

TEST(ResourceContract, DirectedPropagationWithoutTheRsmInjectionIsRefusedNamingBoth) {
  const std::string message = test::errorOf(
      [] {
        resolveRequirements(composition("sky_columns", "none", "directed"), 1,
                            skyLightUses(glm::vec3(1.0f)));
      });
  EXPECT_TRUE(test::contains(message, "[propagation] type = \"directed\" consumes 'normal_grid'"))
      << message;
  EXPECT_TRUE(test::contains(message, "add [injection] type = \"rsm_vpl\"")) << message;
  // The same composition with the RSM injection has the normal grid.
  EXPECT_TRUE(resolveRequirements(composition("rsm_vpl", "none", "directed"), 1)
                  .has(kNormalGrid));
}

TEST(ResourceContract, ASkyNobodyInjectsIsRefusedNamingTheSkyAndItsInjection) {
  const std::string message = test::errorOf(
      [] {
        resolveRequirements(composition("rsm_vpl", "none", "standard"), 1,
                            skyLightUses(glm::vec3(0.5f)));
      });
  EXPECT_TRUE(test::contains(message, "[sky] radiance consumes 'sky_light'")) << message;
  EXPECT_TRUE(test::contains(message, "[injection] type = \"sky_columns\"")) << message;
  EXPECT_TRUE(test::contains(message, "[[injection.also]]")) << message;
  // No sky, nothing consumed.
  EXPECT_FALSE(resolveRequirements(composition("rsm_vpl", "none", "standard"), 1)
                   .has(kSkyLight));
}

struct Probe;  // a test's own resource type (below)
constexpr ResourceKey<Probe> kProbe{"test_probe", "a test's probe"};

TEST(ResourceContract, AResourceNoRegisteredStrategyProducesIsRefusedSayingSo) {
  ResourceUses reader;
  reader.consumes(kProbe, "the test");
  const std::string message =
      test::errorOf([&] { resolveResources({{"[rendering] type = \"reader\"", reader}}); });
  EXPECT_TRUE(test::contains(message, "[rendering] type = \"reader\" consumes 'test_probe' "
                                      "(a test's probe) for the test"))
      << message;
  EXPECT_TRUE(test::contains(message, "no registered strategy produces it")) << message;
}

// ---- b. only what is produced and used ------------------------------------------------------------

TEST(ResourceContract, AResourceExistsOnlyWhenProducedAndUsed) {
  ResourceUses producer, reader, consumer;
  producer.produces(kGeometryVolume, 1);
  producer.produces(kSurfaceAlbedo);
  reader.reads(kGeometryVolume);
  reader.reads(kNormalGrid);  // nobody produces it: no error, no grid
  consumer.consumes(kSurfaceAlbedo);

  const auto alone = resolveResources({{"producer", producer}});
  EXPECT_TRUE(alone.empty());
  const auto read = resolveResources({{"producer", producer}, {"reader", reader}});
  ASSERT_EQ(read.size(), 1u);
  EXPECT_EQ(read.begin()->first, "geometry_volume");
  const auto both =
      resolveResources({{"producer", producer}, {"reader", reader}, {"consumer", consumer}});
  EXPECT_EQ(both.size(), 2u);
  EXPECT_TRUE(both.count("surface_albedo"));

  // The shipped compositions: the GV occlusion's albedo only with bounces.
  EXPECT_TRUE(resolveRequirements(composition("rsm_vpl", "geometry_volume", "standard"), 1)
                  .has(kGeometryVolume));
  EXPECT_FALSE(resolveRequirements(composition("rsm_vpl", "geometry_volume", "standard"), 1)
                   .has(kSurfaceAlbedo));
  EXPECT_FALSE(resolveRequirements(composition("rsm_vpl", "none", "standard"), 1)
                   .has(kNormalGrid));  // the RSM injection produces it, nobody uses it
}

// ---- c. a resource of the test's own, through the pipeline -----------------------------------------

struct Probe {
  explicit Probe(const ResourceSetup& setup, float mark) : cells(setup.grid.cellCount()), mark(mark) {}
  void place(const GridGeometry& lightGrid) { origin = lightGrid.origin; }
  void clear() { ++clears; }
  std::size_t memoryBytes() const { return std::size_t(cells); }  // "one byte per cell"
  int cells;
  float mark;
  glm::vec3 origin{0.0f};
  int clears = 0;
  int writes = 0;
};

class ProbeWriter final : public OcclusionStrategy {
public:
  int maxShOrder() const override { return 3; }
  void declare(ResourceUses& uses) const override { uses.produces(kProbe, 7.0f); }
  void prepare(const StrategySetup& setup) override { allocated_ = setup.requirements.has(kProbe); }
  void inject(Frame& frame) override {
    if (allocated_) ++frame.get(kProbe).writes;
  }

private:
  bool allocated_ = false;
};

// Records, per frame, what each level's probe held when rendering read it.
class ProbeReader final : public RenderingStrategy {
public:
  int maxShOrder() const override { return 3; }
  void declare(ResourceUses& uses) const override { uses.consumes(kProbe); }
  void prepare(const StrategySetup& setup) override {
    sceneMaterials = setup.scene ? int(setup.scene->materials().size()) : -1;
    lightViews = setup.lightMaps ? setup.lightMaps->views : -1;
    imageSize = setup.imageSize;
  }
  void render(Frame& frame) override {
    seen.clear();
    // Rendering runs once with level 0's resources; the pipeline's other levels are its own.
    seen.push_back(frame.get(kProbe));
  }
  std::vector<Probe> seen;
  int sceneMaterials = 0, lightViews = 0;
  glm::ivec2 imageSize{0};
};

TEST(ResourceContract, ThePipelineAllocatesATestsOwnResourcePerLevelAndHandsItToItsConsumer) {
  test::glTestContext();
  Experiment e = loadExperiment("", {"output.width=24", "output.height=16", "grid.resolution=8",
                                     "cascades.levels=2"});
  // The default experiment's composition, with a test's own producer and consumer.
  Strategies strategies = composition("rsm_vpl", "none", "standard");
  strategies.occlusion = std::make_unique<ProbeWriter>();
  strategies.occlusion->setRegisteredName("probe_writer");
  auto reader = std::make_unique<ProbeReader>();
  reader->setRegisteredName("probe_reader");
  ProbeReader* probeReader = reader.get();
  strategies.rendering.push_back(std::move(reader));
  const std::size_t materials = e.scene.materials.size();
  ShaderCompiler shaders;
  Pipeline pipeline(e.scene, e.camera, e.settings, test::lpvMethod(std::move(strategies)), shaders);

  // d. prepare() saw the scene, its light views and the image size.
  EXPECT_EQ(probeReader->sceneMaterials, int(materials));
  EXPECT_GT(probeReader->lightViews, 0);
  EXPECT_EQ(probeReader->imageSize, glm::ivec2(24, 16));

  // One probe per level, each the level's size: the memory report sums them.
  EXPECT_EQ(pipeline.memoryReport().at("test_probe").get<std::size_t>(),
            std::size_t(2 * 8 * 8 * 8));
  pipeline.renderFrame();
  pipeline.renderFrame();
  ASSERT_EQ(probeReader->seen.size(), 1u);
  const Probe& level0 = probeReader->seen[0];
  EXPECT_EQ(level0.mark, 7.0f);          // the producer's argument reached the constructor
  EXPECT_EQ(level0.clears, 2);           // cleared before each frame
  EXPECT_EQ(level0.writes, 2);           // and written by its producer in each
  EXPECT_EQ(level0.origin, test::lpvOf(pipeline).levels()[0].geometry.origin);  // placed with its level
}

// ---- e. the table's own checks -------------------------------------------------------------------

TEST(ResourceContract, ATableRefusesAMissingResourceAndAWrongTypeByName) {
  ResourceTable table;
  EXPECT_EQ(table.find(kNormalGrid), nullptr);
  EXPECT_TRUE(test::contains(test::errorOf([&] { table.get(kNormalGrid); }), "'normal_grid'"));
  SurfaceAlbedo albedo;
  table.put(kSurfaceAlbedo, albedo);
  EXPECT_EQ(table.find(kSurfaceAlbedo), &albedo);
  constexpr ResourceKey<NormalGrid> impostor{"surface_albedo", "the same name, another type"};
  EXPECT_TRUE(test::contains(test::errorOf([&] { table.find(impostor); }), "'surface_albedo'"));
}

}  // namespace
}  // namespace lpvlab
