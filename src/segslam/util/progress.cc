#include "segslam/util/progress.h"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>

namespace segslam::util {

ProgressBar::ProgressBar(std::string label, std::size_t total, std::string unit)
    : label_(std::move(label)),
      total_(total),
      unit_(std::move(unit)),
      interactive_(isatty(fileno(stderr)) != 0),
      start_(std::chrono::steady_clock::now()),
      last_draw_(start_) {}

ProgressBar::~ProgressBar() { finish(); }

void ProgressBar::advance(std::size_t steps) {
  done_ = std::min(total_, done_ + steps);
  draw(false);
}

void ProgressBar::finish() {
  if (finished_) return;
  draw(true);
  finished_ = true;
  if (interactive_) std::fputc('\n', stderr);
}

double ProgressBar::elapsedSeconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void ProgressBar::draw(bool force) {
  const auto now = std::chrono::steady_clock::now();
  const double fraction = total_ == 0 ? 1.0 : static_cast<double>(done_) / total_;
  const int decile = static_cast<int>(fraction * 10.0);
  if (interactive_) {
    if (!force && now - last_draw_ < std::chrono::milliseconds(100)) return;
  } else if (!force && decile == last_decile_) {
    return;
  } else if (force && decile == last_decile_) {
    return;
  }
  last_draw_ = now;
  last_decile_ = decile;
  const double elapsed = elapsedSeconds();
  const double rate = elapsed > 0.0 ? done_ / elapsed : 0.0;
  const double eta = rate > 0.0 ? (total_ - done_) / rate : 0.0;
  constexpr int kWidth = 24;
  const int filled = static_cast<int>(fraction * kWidth);
  const std::string bar = std::string(filled, '#') + std::string(kWidth - filled, '-');
  const std::string line = fmt::format("{} [{}] {:3.0f}% {}/{}  {:.1f} {}/s  ETA {:.1f}s", label_,
                                       bar, fraction * 100.0, done_, total_, rate, unit_, eta);
  if (interactive_) {
    fmt::print(stderr, "\r{}\x1b[K", line);
  } else {
    fmt::print(stderr, "{}\n", line);
  }
  std::fflush(stderr);
}

}  // namespace segslam::util
