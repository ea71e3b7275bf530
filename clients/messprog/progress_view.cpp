// Drawing the progress line.
#include "progress_view.hpp"

#include <algorithm>

namespace imess::messprog {
namespace {
constexpr int kBarWidth = 30;
constexpr const char* kClearLine = "\r\x1b[K";  // carriage return, erase to the end of the line
}  // namespace

int ProgressView::percent(const BlockEvent& b) {
  if (b.total == 0 || b.index == 0) return 0;
  const auto done = std::min(b.index - 1, b.total);
  return static_cast<int>(done * 100 / b.total);
}

std::string ProgressView::bar(const BlockEvent& b, int pct) {
  const int filled = pct * kBarWidth / 100;
  std::string text = b.name + " [" + std::string(static_cast<std::size_t>(filled), '#') +
                     std::string(static_cast<std::size_t>(kBarWidth - filled), '-') + "] ";
  const std::string p = std::to_string(pct);
  text += std::string(3 - std::min<std::size_t>(3, p.size()), ' ') + p + "%  line " + std::to_string(b.line) +
          "  block " + std::to_string(b.index) + "/" + std::to_string(b.total);
  return text;
}

std::string ProgressView::update(const BlockEvent& b, Clock::time_point now) {
  last_ = b;
  if (terminal_) {
    shown_ = true;
    return kClearLine + bar(b, percent(b));
  }
  if (printed_ && now - *printed_ < std::chrono::seconds(1)) return {};
  printed_ = now;
  return b.name + ": " + std::to_string(percent(b)) + "% line " + std::to_string(b.line) + " block " +
         std::to_string(b.index) + "/" + std::to_string(b.total) + "\n";
}

std::string ProgressView::clear() {
  if (!terminal_ || !shown_) return {};
  shown_ = false;
  return kClearLine;
}

std::string ProgressView::redraw() {
  if (!terminal_ || !last_) return {};
  shown_ = true;
  return kClearLine + bar(*last_, percent(*last_));
}

std::string ProgressView::done(bool ok) {
  if (!terminal_ || !last_) return {};
  shown_ = false;
  return kClearLine + bar(*last_, ok ? 100 : percent(*last_)) + "\n";
}

}  // namespace imess::messprog
