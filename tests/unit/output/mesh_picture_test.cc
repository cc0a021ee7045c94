#include <output/mesh_picture.h>

#include <gtest/gtest.h>

#include <array>
#include <filesystem>
#include <fstream>

#include "test_meshes.h"

namespace FloorBlock::Output
{
  namespace
  {
    /** Big-endian 32-bit integer at @p offset of a byte array. */
    unsigned int
    big_endian(const std::array<unsigned char, 24> &bytes,
               const unsigned int                   offset)
    {
      return (bytes[offset] << 24) | (bytes[offset + 1] << 16) |
             (bytes[offset + 2] << 8) | bytes[offset + 3];
    }
  } // namespace

  TEST(MeshPicture, WritesPngOfRequestedWidth)
  {
    const auto       &scene = Geometry::Testing::meshed_scene("default");
    const std::string path =
      Geometry::Testing::scratch_folder() + "/default.png";
    MeshPictureOptions options;
    options.width_pixels = 1200;
    options.title        = "default scene";
    write_mesh_picture(scene.triangulation, path, options);

    std::ifstream                 file(path, std::ios::binary);
    std::array<unsigned char, 24> header{};
    file.read(reinterpret_cast<char *>(header.data()), header.size());
    ASSERT_TRUE(file.good());
    // PNG signature, then the IHDR chunk with width and height.
    const std::array<unsigned char, 8> signature{
      {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'}};
    for (unsigned int index = 0; index < signature.size(); ++index)
      EXPECT_EQ(header[index], signature[index]);
    EXPECT_EQ(big_endian(header, 16), options.width_pixels);
    EXPECT_GT(big_endian(header, 20), 100u);
    EXPECT_GT(std::filesystem::file_size(path), 10000u);
  }
} // namespace FloorBlock::Output
