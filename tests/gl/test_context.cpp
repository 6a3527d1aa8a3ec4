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
// The child ends with _Exit, which skips LeakSanitizer's check at exit in the checked build: on
// some machines (an AMD EPYC with llvmpipe at 256 bits; not the Intel ones before it) the EGL path
// leaves an allocation made from code LSan finds in no module (llvmpipe's JIT code, or a library
// unloaded by then), so tests/sanitizers/lsan.supp cannot name it, and LSan's fast unwinder sees
// no other frame (with fast_unwind_on_malloc=0 it finds Mesa's frames and the file suppresses it,
// at many times the run time). What this test checks is the backend the child reports;
// lpvlab's own leaks are checked by the tests that create contexts in the test process.
[[noreturn]] void exitWithoutLeakCheck(int status) {
  std::fflush(stderr);
  std::_Exit(status);
}

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
        exitWithoutLeakCheck(1);
      } catch (const Error&) {
      }
    }
    exitWithoutLeakCheck(0);
  } catch (const Error& e) {
    std::fprintf(stderr, "Error: %s\n", e.what());
    exitWithoutLeakCheck(1);
  }
}

TEST(GlContext, AutoTakesEglBeforeOsMesa) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(createAutoInChild(), testing::ExitedWithCode(0), "backend=(osmesa|egl) renderer=");
}

}  // namespace
}  // namespace lpvlab
