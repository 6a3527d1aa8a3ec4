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

// In a fresh process as above: "auto" gives osmesa, or egl on something other than Mesa's CPU
// renderers (EGL offers llvmpipe too, which auto must not take in place of osmesa).
void createAutoInChild() {
  try {
    auto context = GlContext::create("auto");
    const std::string renderer = context->renderer();
    std::fprintf(stderr, "backend=%s renderer=%s\n", context->backend().c_str(), renderer.c_str());
    const bool software = renderer.find("llvmpipe") != std::string::npos ||
                          renderer.find("softpipe") != std::string::npos;
    std::exit(context->backend() == "osmesa" || !software ? 0 : 1);
  } catch (const Error& e) {
    std::fprintf(stderr, "Error: %s\n", e.what());
    std::exit(1);
  }
}

TEST(GlContext, AutoGivesOsMesaOrAGpu) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(createAutoInChild(), testing::ExitedWithCode(0), "backend=(osmesa|egl) renderer=");
}

}  // namespace
}  // namespace lpvlab
