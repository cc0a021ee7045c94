#include <common/atomic_file.h>

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace
{
  std::filesystem::path
  fresh_directory(const std::string &name)
  {
    const auto directory =
      std::filesystem::temp_directory_path() /
      ("floorblock_" + name + "_" + std::to_string(::getpid()));
    std::filesystem::remove_all(directory);
    return directory;
  }

  std::string
  read(const std::filesystem::path &path)
  {
    std::ifstream     in(path);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
  }
} // namespace

// The tool shall write result files whole or not at all, leaving no temporary.
TEST(AtomicFile, WritesContentAndLeavesNoTemporary)
{
  const auto directory = fresh_directory("atomic");
  const auto target    = directory / "sub" / "summary.json";
  FloorBlock::write_file_atomically(target.string(), "{\"a\": 1}\n");
  EXPECT_EQ(read(target), "{\"a\": 1}\n");
  unsigned int n_files = 0;
  for ([[maybe_unused]] const auto &entry :
       std::filesystem::directory_iterator(target.parent_path()))
    ++n_files;
  EXPECT_EQ(n_files, 1u);
  std::filesystem::remove_all(directory);
}

// The tool shall replace an existing result file in one step.
TEST(AtomicFile, ReplacesExistingFile)
{
  const auto directory = fresh_directory("replace");
  const auto target    = directory / "x.csv";
  FloorBlock::write_file_atomically(target.string(), "old");
  FloorBlock::write_file_atomically(target.string(), "new");
  EXPECT_EQ(read(target), "new");
  std::filesystem::remove_all(directory);
}

// The tool shall report an unwritable destination instead of pretending
// success.
TEST(AtomicFile, ThrowsWhenFolderCannotBeCreated)
{
  EXPECT_THROW(FloorBlock::write_file_atomically("/proc/floorblock/x.txt", "x"),
               std::exception);
}
