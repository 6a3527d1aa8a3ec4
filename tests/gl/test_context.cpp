#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>

#include "framework/core/error.h"
#include "framework/gl/context.h"
#include "gl_test_context.h"

namespace lpvlab {
namespace {

TEST(GlContext, OsMesaGivesCore45OnLlvmpipe) {
  GlContext& context = test::glTestContext();
  EXPECT_EQ(context.backend(), "osmesa");
  EXPECT_EQ(context.version().rfind("4.5 (Core Profile)", 0), 0u) << context.version();
  EXPECT_NE(context.renderer().find("llvmpipe"), std::string::npos) << context.renderer();
}

TEST(GlContext, UnknownBackendListsTheValidOnes) {
  try {
    GlContext::create("bogus");
    FAIL() << "no Error";
  } catch (const Error& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("'bogus'"), std::string::npos) << message;
    for (const std::string& name : GlContext::backends())
      EXPECT_NE(message.find(name), std::string::npos) << message;
    EXPECT_NE(message.find("auto"), std::string::npos) << message;
  }
}

TEST(GlContext, SecondContextIsRefused) {
  test::glTestContext();
  try {
    GlContext::create("osmesa");
    FAIL() << "no Error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("one already exists"), std::string::npos) << e.what();
  }
}

// Creates `backend` in a fresh process (a death-test child, which runs this test alone and so
// has no other context) and exits 0 printing what it got, or exits 0 printing an Error that
// begins with the backend's name; anything else (another exception, a crash) fails.
void createInChild(const std::string& backend) {
  try {
    auto context = GlContext::create(backend);
    std::fprintf(stderr, "backend=%s renderer=%s\n", context->backend().c_str(),
                 context->renderer().c_str());
    std::exit(0);
  } catch (const Error& e) {
    std::fprintf(stderr, "Error: %s\n", e.what());
    std::exit(std::string(e.what()).rfind(backend, 0) == 0 ? 0 : 1);
  }
}

TEST(GlContext, EglWorksOrFailsCleanly) {
  if (GlContext::backends().size() < 2) GTEST_SKIP() << "built without EGL";
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(createInChild("egl"), testing::ExitedWithCode(0),
              "backend=egl renderer=|Error: egl: ");
}

// In a fresh process as above: "auto" takes EGL (a GPU, else Mesa's software device) before
// OSMesa, which it falls back to only where EGL gives no context (Mesa 25.1 has no OSMesa).
void createAutoInChild() {
  try {
    std::string backend;
    {
      auto context = GlContext::create("auto");
      backend = context->backend();
      std::fprintf(stderr, "backend=%s renderer=%s\n", backend.c_str(), context->renderer().c_str());
    }
    if (backend == "osmesa" && GlContext::backends().size() > 1) {
      try {
        GlContext::create("egl");
        std::fprintf(stderr, "but EGL gives a context: auto should have taken it\n");
        std::exit(1);
      } catch (const Error&) {
      }
    }
    std::exit(0);
  } catch (const Error& e) {
    std::fprintf(stderr, "Error: %s\n", e.what());
    std::exit(1);
  }
}

TEST(GlContext, AutoTakesEglBeforeOsMesa) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(createAutoInChild(), testing::ExitedWithCode(0), "backend=(osmesa|egl) renderer=");
}

}  // namespace
}  // namespace lpvlab
