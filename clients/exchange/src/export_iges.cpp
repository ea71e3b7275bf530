// .igs: IGES 5.3, one entity 116 (point) per point, grouped by one entity 402 form 7. Fixed
// 80-column records: data in
// columns 1-72, the section letter (S G D P T) in 73, the sequence number in 74-80; parameter
// records use 1-64 and carry their directory entry's number in 66-72.
#include <cstdio>
#include <vector>

#include "writers.hpp"

namespace imess::exchange::writers {
namespace {

std::string hollerith(const std::string& s) { return std::to_string(s.size()) + "H" + s; }


class Section {
 public:
  explicit Section(char letter) : letter_(letter) {}
  // A record: `data` padded to 72 columns, then letter and sequence number.
  void record(const std::string& data) {
    char tail[16];
    std::snprintf(tail, sizeof tail, "%c%7d\n", letter_, ++count_);
    std::string line = data;
    line.resize(72, ' ');
    text_ += line + tail;
  }
  // Parameters packed into records of `width` columns, never splitting one; `suffix` (the DE
  // pointer for the P section) fills columns width+1..72.
  void packed(const std::vector<std::string>& params, char last, std::size_t width,
              const std::string& suffix = {}) {
    std::string line;
    for (std::size_t i = 0; i < params.size(); ++i) {
      std::string item = params[i] + (i + 1 == params.size() ? last : ',');
      if (!line.empty() && line.size() + item.size() > width) {
        flush(line, width, suffix);
        line.clear();
      }
      line += item;
    }
    flush(line, width, suffix);
  }
  int count() const { return count_; }
  const std::string& text() const { return text_; }

 private:
  void flush(std::string line, std::size_t width, const std::string& suffix) {
    line.resize(width, ' ');
    record(line + suffix);
  }
  char letter_;
  int count_ = 0;
  std::string text_;
};

std::string field(const std::string& s) {  // 8 columns, right-justified
  char buf[16];
  std::snprintf(buf, sizeof buf, "%8s", s.c_str());
  return buf;
}
std::string field(int v) { return field(std::to_string(v)); }

// One entity: its parameter records (P), then its two directory records (D).
void entity(Section& directory, Section& parameters, int type, int form, const std::string& status,
            const std::string& label, int subscript, const std::vector<std::string>& params) {
  const int de = directory.count() + 1;  // this entity's first D record
  const int first_p = parameters.count() + 1;
  char de_pointer[16];
  std::snprintf(de_pointer, sizeof de_pointer, " %7d", de);
  parameters.packed(params, ';', 64, de_pointer);
  const int lines = parameters.count() - first_p + 1;
  directory.record(field(type) + field(first_p) + field(0) + field(0) + field(0) + field(0) + field(0) + field(0) +
                   status);
  directory.record(field(type) + field(0) + field(0) + field(lines) + field(form) + field("") + field("") +
                   field(label) + field(subscript));
}

}  // namespace

std::string iges(const ExportData& d) {
  Section start('S'), global('G'), directory('D'), parameters('P');
  start.record(d.source + ": " + std::to_string(d.points.size()) + " measured points as IGES entity 116, mm" +
               (d.frame.empty() ? "" : ", frame " + d.frame));

  const std::string stamp = local_timestamp("%Y%m%d.%H%M%S");
  double max_coord = 1.0;
  for (const auto& p : d.points) max_coord = std::max(max_coord, p.cwiseAbs().maxCoeff());
  double resolution = 1.0;
  for (int i = 0; i < d.decimals; ++i) resolution /= 10.0;
  global.packed({hollerith(","), hollerith(";"), hollerith("IMESS points"), hollerith(d.file_name),
                 hollerith("IMESS"), hollerith(d.source), "32", "38", "6", "308", "15", hollerith("IMESS points"),
                 "1.0", "2", hollerith("MM"), "1", "1.0", hollerith(stamp), real_with_point(resolution, 12),
                 real_with_point(max_coord, 3), hollerith("IMESS"), hollerith("IMESS"), "11", "0", hollerith(stamp)},
                ';', 72);

  // The points, logically dependent (status 00020000) on one group at the end: a reader
  // (OCC, FreeCAD) then sees one compound rather than N free shapes.
  std::vector<std::string> members;
  for (std::size_t i = 0; i < d.points.size(); ++i) {
    const auto& p = d.points[i];
    members.push_back(std::to_string(directory.count() + 1));
    entity(directory, parameters, 116, 0, "00020000", "POINT", static_cast<int>(i + 1),
           {"116", real_with_point(p.x(), d.decimals), real_with_point(p.y(), d.decimals), real_with_point(p.z(), d.decimals), "0"});
  }
  // 402 form 7: unordered group without back pointers — the measured point set.
  members.insert(members.begin(), {"402", std::to_string(d.points.size())});
  entity(directory, parameters, 402, 7, "00000000", "POINTS", 1, members);

  Section terminate('T');
  char counts[40];
  std::snprintf(counts, sizeof counts, "S%7dG%7dD%7dP%7d", start.count(), global.count(), directory.count(),
                parameters.count());
  terminate.record(counts);
  return start.text() + global.text() + directory.text() + parameters.text() + terminate.text();
}

}  // namespace imess::exchange::writers
