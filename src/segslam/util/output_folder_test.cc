#include "segslam/util/output_folder.h"

#include <gtest/gtest.h>

#include <fstream>

#include "segslam/testing/test_support.h"
#include "segslam/util/error.h"

namespace segslam::util {
namespace {

std::string errorOf(const std::filesystem::path& folder) {
  try {
    createOutputFolder(folder);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(OutputFolder, CreatesTheFolderAndItsParents) {
  const segslam::testing::ScopedTempDir temp;
  const auto folder = temp.path() / "a" / "b";
  createOutputFolder(folder);
  EXPECT_TRUE(std::filesystem::is_directory(folder));
  createOutputFolder(folder);  // already there: nothing to do
  createFolderFor(temp.path() / "c" / "file.json");
  EXPECT_TRUE(std::filesystem::is_directory(temp.path() / "c"));
  EXPECT_NO_THROW(createFolderFor("file.json"));
}

TEST(OutputFolder, AFileInTheWayIsNamedWithTheReason) {
  const segslam::testing::ScopedTempDir temp;
  const auto file = temp.path() / "file.txt";
  std::ofstream(file) << "x";
  EXPECT_EQ(errorOf(file),
            "cannot create output folder " + file.string() + ": a file of that name is in the way");
  EXPECT_EQ(errorOf(file / "run"),
            "cannot create output folder " + (file / "run").string() + ": Not a directory");
  try {
    createFolderFor(file / "plots" / "a.svg");
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()),
              "cannot create output folder " + (file / "plots").string() + ": Not a directory");
  }
}

}  // namespace
}  // namespace segslam::util
