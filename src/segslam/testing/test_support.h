#pragma once

// Helpers for the test suite only (header-only, never linked into the library).

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <random>
#include <sstream>
#include <string>

namespace segslam::testing {

// The shared data folder (../shared beside the project): $SEGSLAM_SHARED_DIR, else
// <source>/../shared. Empty when neither exists.
inline std::optional<std::filesystem::path> sharedDir() {
  if (const char* env = std::getenv("SEGSLAM_SHARED_DIR");
      env && std::filesystem::is_directory(env)) {
    return std::filesystem::path(env);
  }
#ifdef SEGSLAM_SOURCE_DIR
  const auto beside = std::filesystem::path(SEGSLAM_SOURCE_DIR) / ".." / "shared";
  if (std::filesystem::is_directory(beside)) return std::filesystem::weakly_canonical(beside);
#endif
  return std::nullopt;
}

// Path inside ../shared/data, or nullopt when ../shared is absent.
inline std::optional<std::filesystem::path> sharedData(const std::string& relative) {
  auto dir = sharedDir();
  if (!dir) return std::nullopt;
  return *dir / "data" / relative;
}

// The whole file as bytes (empty when it cannot be read: tests compare it with what they expect).
inline std::string fileContents(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

// Writes `file`: a copy of the model config `shipped` whose "  model: " line names `model`
// instead (a config like the shipped one, with its network somewhere else or missing).
inline void writeConfigNamingModel(const std::filesystem::path& shipped,
                                   const std::filesystem::path& file,
                                   const std::filesystem::path& model) {
  std::ifstream in(shipped);
  std::ofstream out(file);
  for (std::string line; std::getline(in, line);) {
    out << (line.starts_with("  model: ") ? "  model: " + model.string() : line) << "\n";
  }
}

// A fresh, empty directory removed when the object goes out of scope.
class ScopedTempDir {
 public:
  ScopedTempDir() {
    std::random_device rd;
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::string name = info ? std::string(info->test_suite_name()) + "." + info->name() : "test";
    path_ =
        std::filesystem::temp_directory_path() / ("segslam_" + name + "_" + std::to_string(rd()));
    std::filesystem::create_directories(path_);
  }
  ~ScopedTempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  ScopedTempDir(const ScopedTempDir&) = delete;
  ScopedTempDir& operator=(const ScopedTempDir&) = delete;
  [[nodiscard]] const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

}  // namespace segslam::testing

// Skips the current test with a clear message when ../shared is not beside the project.
#define SEGSLAM_REQUIRE_SHARED(path_var, relative)                                           \
  const auto path_var##_opt = ::segslam::testing::sharedData(relative);                      \
  if (!path_var##_opt || !std::filesystem::exists(*path_var##_opt)) {                        \
    GTEST_SKIP() << "../shared/data/" << (relative)                                          \
                 << " not found (set SEGSLAM_SHARED_DIR or put shared/ beside the project)"; \
  }                                                                                          \
  const std::filesystem::path path_var = *path_var##_opt
