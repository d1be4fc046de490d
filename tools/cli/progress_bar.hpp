// A progress bar on stderr for work that takes long (an atlas of 10^7 curves): drawn only when
// stderr is a terminal (a log or a pipe gets no carriage returns), at most ten times a second.
// The library reports the fraction done through a callback; this draws it.
#pragma once

#include <chrono>
#include <functional>
#include <string>

namespace koppel::cli {

class ProgressBar {
 public:
  // `enabled`: false for --quiet; the bar is drawn only if stderr is also a terminal.
  ProgressBar(std::string label, bool enabled);
  ~ProgressBar();  // clears the bar's line
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;

  void Update(double fraction);
  // The callback to hand to the library (empty when nothing is drawn: no cost there).
  std::function<void(double)> Callback();

 private:
  std::string label_;
  bool drawing_;
  bool drawn_ = false;
  int last_permille_ = -1;
  std::chrono::steady_clock::time_point start_, last_draw_;
};

}  // namespace koppel::cli
