#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include "framework/scene/texture_loader.h"
#include "scene/scene_test_support.h"

namespace lpvlab {
namespace {

// A .glb's JPEG goes through OpenImageIO's memory reader: it must decode as the file does.
TEST(TextureLoader, DecodesJpegFromMemoryAsFromFile) {
  const std::string path = test::sharedScene("breakfast_room/marble.jpg");
  const TextureImage fromFile = readTextureFile(path);
  const std::string bytes = test::readFile(path);
  const TextureImage fromMemory = decodeTexture(bytes.data(), bytes.size(), "jpg", "marble");
  EXPECT_GT(fromFile.width, 0);
  EXPECT_EQ(fromMemory.width, fromFile.width);
  EXPECT_EQ(fromMemory.height, fromFile.height);
  EXPECT_TRUE(fromMemory.rgba8 == fromFile.rgba8);
  EXPECT_EQ(fromMemory.path, "marble");
}

TEST(TextureLoader, GreyBecomesOpaqueRgb) {
  test::TempDir dir;
  const std::string path = dir.file("grey.png");
  const std::uint8_t texels[] = {0, 100, 255};
  auto out = OIIO::ImageOutput::create(path);
  ASSERT_TRUE(out && out->open(path, OIIO::ImageSpec(3, 1, 1, OIIO::TypeDesc::UINT8)));
  ASSERT_TRUE(out->write_image(OIIO::TypeDesc::UINT8, texels));
  out->close();
  const TextureImage texture = readTextureFile(path);
  EXPECT_EQ(texture.rgba8,
            (std::vector<std::uint8_t>{0, 0, 0, 255, 100, 100, 100, 255, 255, 255, 255, 255}));
}

TEST(TextureLoader, UndecodableBytesNameTheTexture) {
  const std::string garbage = "not an image at all";
  const std::string message = test::errorMessage(
      [&] { decodeTexture(garbage.data(), garbage.size(), "png", "scene.glb:*3"); });
  EXPECT_NE(message.find("scene.glb:*3"), std::string::npos) << message;
}

}  // namespace
}  // namespace lpvlab
