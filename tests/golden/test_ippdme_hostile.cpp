// Hostile I++ DME lines of issue 26 (items 1, 2, 8) against messd's parts in virtual time: each
// is refused with the spec's error, and the daemon serves both ports on afterwards.
#include <catch2/catch.hpp>

#include <algorithm>
#include <string>
#include <vector>

#include "ipp_script.hpp"

namespace imess::golden {
namespace {

std::vector<std::string> lines_of(const std::vector<Entry>& out, int client) {
  std::vector<std::string> lines;
  for (const auto& e : out)
    if (e.kind == EntryKind::Receive && e.client == client) lines.push_back(e.text);
  return lines;
}

bool has(const std::vector<std::string>& lines, const std::string& line) {
  return std::find(lines.begin(), lines.end(), line) != lines.end();
}

bool has_prefix(const std::vector<std::string>& lines, const std::string& prefix) {
  return std::any_of(lines.begin(), lines.end(), [&](const std::string& l) { return l.rfind(prefix, 0) == 0; });
}


}  // namespace

// Issue 26, 1: this line made messd exit 2 ("frame has a non-finite rotation or translation
// element"), both ports gone. Now it is refused and the session and MESSD clients go on.
TEST_CASE("I++ DME hostile: SetCsyTransformation with 1.7e308 offsets is refused 0509, messd serves on") {
  const auto out = replay(parse_transcript(kIppStart +
                                               "2> 00002 SetCsyTransformation(PartCsy, 1.7e308, 1.7e308, 0, 0, 45, 0)\n"
                                               "2> 00003 ClearAllErrors()\n2> 00004 Get(X())\n> Status\n",
                                           "hostile"),
                          "hostile");
  const auto ipp = lines_of(out, 2);
  INFO(ipp.size());
  CHECK(has(ipp, "00002 ! Error(3, 0509, SetCsyTransformation, \"Bad argument\")"));
  CHECK(has(ipp, "00004 # X(430.0000)"));
  CHECK(has_prefix(lines_of(out, 1), "Ok Status "));
}

// Issue 26, 2: 1e300 was taken, stored as frame PartCsy and printed cut short. Offsets are
// bounded as MESSD's SetFrame bounds a frame's origin: ±1e6 mm.
TEST_CASE("I++ DME hostile: SetCsyTransformation beyond 1e6 mm is refused 0509 and stores no frame") {
  const auto out = replay(parse_transcript(kIppStart +
                                               "2> 00002 SetCsyTransformation(PartCsy, 1e300, 0, 0, 0, 0, 0)\n"
                                               "2> 00003 ClearAllErrors()\n"
                                               "2> 00004 SetCsyTransformation(MoveableMachineCsy, 0, -1000000.5, 0, 0, 0, 0)\n"
                                               "2> 00005 ClearAllErrors()\n"
                                               "2> 00006 SetCsyTransformation(PartCsy, 1000000, -1000000, 0, 0, 0, 0)\n"
                                               "> Frames\n",
                                           "hostile"),
                          "hostile");
  const auto ipp = lines_of(out, 2);
  CHECK(has(ipp, "00002 ! Error(3, 0509, SetCsyTransformation, \"Bad argument\")"));
  CHECK(has(ipp, "00004 ! Error(3, 0509, SetCsyTransformation, \"Bad argument\")"));
  CHECK(has(ipp, "00006 %"));  // the bound itself is accepted
  CHECK_FALSE(has_prefix(ipp, "00006 !"));
  CHECK(has(lines_of(out, 1), "Ok Frames Active PartCsy Names machine PartCsy"));
}

// Issue 26, 8: the normal's length overflowed (1e200 squared) and the direction became 1010.
TEST_CASE("I++ DME hostile: PtMeas with IJK(-1e200, 0, 0) measures as IJK(-1, 0, 0)") {
  auto measure = [](const std::string& ijk) {
    const auto out = replay(parse_transcript(kIppStart +
                                                 "2> 00002 GoTo(X(460), Y(350), Z(100))\n= 3000 ms\n"
                                                 "2> 00003 GoTo(Z(40))\n= 3000 ms\n"
                                                 "2> 00004 PtMeas(X(475), Y(350), Z(40), IJK(" + ijk + "))\n= 4000 ms\n",
                                             "hostile"),
                            "hostile");
    std::string point;
    for (const auto& l : lines_of(out, 2))
      if (l.rfind("00004 #", 0) == 0 || l.rfind("00004 !", 0) == 0) point = l;
    return point;
  };
  const std::string unit = measure("-1, 0, 0");
  REQUIRE(unit.rfind("00004 # X(", 0) == 0);
  CHECK(measure("-1e200, 0, 0") == unit);
  CHECK(measure("-1e-200, 0, 0") == unit);
}

// Issue 26, 8: a target beyond every limit came back 0511 (the planner refused a non-finite
// pose); it is the spec's out-of-range error.
TEST_CASE("I++ DME hostile: GoTo to a target that is infinite in machine coordinates gets 2500") {
  const auto out = replay(parse_transcript(kIppStart +
                                               "2> 00002 SetCsyTransformation(PartCsy, 0, 0, 0, 0, 45, 0)\n"
                                               "2> 00003 SetCoordSystem(PartCsy)\n"
                                               "2> 00004 GoTo(X(1.7e308), Y(1.7e308))\n"
                                               "2> 00005 ClearAllErrors()\n"
                                               "2> 00006 PtMeas(X(1.7e308), Y(1.7e308), IJK(0, 0, 1))\n",
                                           "hostile"),
                          "hostile");
  const auto ipp = lines_of(out, 2);
  CHECK(has(ipp, "00004 ! Error(3, 2500, GoTo, \"Machine limit encountered [Move Out Of Limits]\")"));
  CHECK(has(ipp, "00006 ! Error(3, 2500, PtMeas, \"Machine limit encountered [Move Out Of Limits]\")"));
}

}  // namespace imess::golden
