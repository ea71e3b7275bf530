// Journal::find_lost / note_lost: the numbers journaled whose records cannot be read back
// (damaged, or missing between files), found at start and named in the daemon's log.
#include <algorithm>

#include "imess/journal/journal.hpp"
#include "journal_files.hpp"
#include "recovery.hpp"

namespace imess::journal {
namespace {

std::string range_text(const LostRange& r) {
  return r.first == r.last ? std::to_string(r.first) : std::to_string(r.first) + " to " + std::to_string(r.last);
}

constexpr std::size_t kMaxNamed = 20;  // warnings in the log; the summary counts all

}  // namespace

void Journal::find_lost(const std::vector<FileScan>& scans) {
  auto add = [this](std::uint64_t first, std::uint64_t last) {
    if (first > last) return;
    if (!lost_.empty() && lost_.back().last + 1 == first)
      lost_.back().last = last;
    else
      lost_.push_back({first, last, 0});
  };
  for (std::size_t i = 0; i < files_.size(); ++i) {
    for (const auto& g : scans[i].gaps) add(g.first, g.last);
    // After a file's last intact record, up to where the next file begins.
    if (i + 1 < files_.size()) add(scans[i].highest ? *scans[i].highest + 1 : files_[i].first, files_[i + 1].first - 1);
  }
}

void Journal::note_lost() {
  const std::uint64_t keep_from = oldest();  // older files may have been deleted just now
  std::erase_if(lost_, [&](const LostRange& r) { return r.last < keep_from; });
  if (!lost_.empty()) lost_.front().first = std::max(lost_.front().first, keep_from);
  std::uint64_t count = 0;
  std::string named;
  for (std::size_t i = 0; i < lost_.size(); ++i) {
    const LostRange& r = lost_[i];
    count += r.last - r.first + 1;
    if (i < 5) named += (i ? ", " : "") + range_text(r);
    if (i == 5) named += ", ...";
    if (i < kMaxNamed) {
      std::string path = files_.front().path;
      for (const auto& f : files_)
        if (f.first <= r.first) path = f.path;
      const bool one = r.first == r.last;
      warnings_.push_back(std::string("journal: ") + (one ? "hit " : "hits ") + range_text(r) +
                          (one ? " cannot be replayed: its record in '" : " cannot be replayed: their records from '") +
                          path + (one ? "' is" : "' on are") + " damaged (the checksum fails) or missing; Replay " +
                          "names " + (one ? "it" : "them") + " as lost");
    }
  }
  if (lost_.size() > kMaxNamed)
    warnings_.push_back("journal: and " + std::to_string(lost_.size() - kMaxNamed) + " more ranges of lost hits");
  std::string kept = "journal: " + config_.dir + ", hits " + std::to_string(oldest()) + " to " + std::to_string(newest_) + " kept";
  if (count > 0) kept += ", " + std::to_string(count) + " of them lost (" + named + ")";
  notes_.push_back(kept + "; the next hit will be " + std::to_string(newest_ + 1));
}

}  // namespace imess::journal
