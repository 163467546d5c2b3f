#pragma once

#include <chrono>
#include <cstddef>
#include <string>

namespace segslam::util {

// A one-line progress bar on stderr with rate and ETA, e.g.
//   synth [#########-----------]  45% 135/300  62.1 frames/s  ETA 2.7s
// Redraws at most ~10 times a second; on a non-terminal stderr it prints a line every 10 %.
class ProgressBar {
 public:
  ProgressBar(std::string label, std::size_t total, std::string unit = "frames");
  ~ProgressBar();
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;

  void advance(std::size_t steps = 1);
  // Draws the final state and ends the line; called by the destructor if not done before.
  void finish();
  [[nodiscard]] double elapsedSeconds() const;

 private:
  void draw(bool force);

  std::string label_;
  std::size_t total_;
  std::string unit_;
  std::size_t done_ = 0;
  bool finished_ = false;
  bool interactive_;
  int last_decile_ = -1;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_draw_;
};

}  // namespace segslam::util
