#include "progress_bar.hpp"

#include <fmt/core.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <utility>

namespace koppel::cli {

ProgressBar::ProgressBar(std::string label, bool enabled)
    : label_(std::move(label)), drawing_(enabled && isatty(STDERR_FILENO) != 0), start_(std::chrono::steady_clock::now()), last_draw_(start_) {}

ProgressBar::~ProgressBar() {
  if (drawn_) std::fputs("\r\033[K", stderr);  // the summary line follows on a clean line
}

void ProgressBar::Update(double fraction) {
  if (!drawing_) return;
  const auto now = std::chrono::steady_clock::now();
  const int permille = static_cast<int>(std::clamp(fraction, 0.0, 1.0) * 1000.0);
  if (permille == last_permille_ || (drawn_ && now - last_draw_ < std::chrono::milliseconds(100) && permille < 1000)) return;
  last_permille_ = permille;
  last_draw_ = now;
  constexpr int kWidth = 30;
  const int filled = permille * kWidth / 1000;
  const double seconds = std::chrono::duration<double>(now - start_).count();
  std::string eta;
  if (permille > 0 && permille < 1000) eta = fmt::format(", {:.0f} s left", seconds * (1000 - permille) / permille);
  std::fputs(fmt::format("\r{} [{}{}] {:5.1f}%{}\033[K", label_, std::string(filled, '#'), std::string(kWidth - filled, '.'), permille / 10.0, eta)
                 .c_str(),
             stderr);
  std::fflush(stderr);
  drawn_ = true;
}

std::function<void(double)> ProgressBar::Callback() {
  if (!drawing_) return {};
  return [this](double fraction) { Update(fraction); };
}

}  // namespace koppel::cli
