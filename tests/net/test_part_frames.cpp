// The controller's part frames: the store on disk, the active frame, names.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <unistd.h>

#include "imess/net/part_frames.hpp"

using imess::metrology::Frame;
using imess::net::PartFrames;
namespace fs = std::filesystem;

namespace {
fs::path temp_dir(const char* name) {
  auto dir = fs::temp_directory_path() / (std::string("imess-part-frames-") + name + "-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}
Frame turned() {
  Eigen::Matrix3d r;
  r << 0, -1, 0, 1, 0, 0, 0, 0, 1;
  return Frame(r, Eigen::Vector3d(400, 300, 80));
}
}  // namespace

TEST_CASE("part frames: machine is always there and active at start") {
  PartFrames f;
  CHECK(f.active() == "machine");
  CHECK(f.names() == std::vector<std::string>{"machine"});
  REQUIRE(f.find("machine"));
  CHECK(f.find("machine")->matrix().isIdentity());
  CHECK(f.find("cube") == nullptr);
  CHECK_FALSE(f.use("cube"));
}

TEST_CASE("part frames: stored frames survive a restart, the active one does not") {
  const auto dir = temp_dir("restart");
  const auto file = dir / "frames.json";
  {
    PartFrames f(file);
    CHECK(f.put("cube", turned()).empty());
    CHECK(f.active() == "cube");
    CHECK(f.put("G54", Frame(Eigen::Matrix3d::Identity(), Eigen::Vector3d(1, 2, 3))).empty());
    CHECK(f.active() == "G54");
    CHECK(f.use("cube"));
  }
  PartFrames again(file);
  CHECK(again.active() == "machine");
  CHECK(again.names() == std::vector<std::string>{"machine", "G54", "cube"});
  REQUIRE(again.find("cube"));
  CHECK(again.find("cube")->matrix().isApprox(turned().matrix(), 0));  // bit-exact round trip
  std::string save_error;
  CHECK(again.use("cube"));
  CHECK(again.remove("cube", save_error));
  CHECK(save_error.empty());
  CHECK(again.active() == "machine");
  CHECK_FALSE(again.remove("cube", save_error));
  CHECK_FALSE(again.remove("machine", save_error));
  CHECK(PartFrames(file).names() == std::vector<std::string>{"machine", "G54"});
  fs::remove_all(dir);
}

TEST_CASE("part frames: a store that does not load is an error naming the file and the key") {
  const auto dir = temp_dir("bad");
  const auto file = dir / "frames.json";
  std::ofstream(file) << R"({"frames": {"cube": {"raw": [[1, 0, 0]]}}})";
  try {
    PartFrames f(file);
    FAIL("a broken store loaded");
  } catch (const imess::metrology::FrameError& e) {
    CHECK_THAT(e.what(), Catch::Contains(file.string()));
    CHECK_THAT(e.what(), Catch::Contains("frames.cube.raw"));
  }
  fs::remove_all(dir);
}

TEST_CASE("part frames: a store that cannot be written keeps the frame for this run and says why") {
  const auto dir = temp_dir("unwritable");
  PartFrames f(dir / "missing-dir" / "frames.json");
  const auto why = f.put("cube", turned());
  CHECK_FALSE(why.empty());
  CHECK(f.active() == "cube");
  REQUIRE(f.find("cube"));
  fs::remove_all(dir);
}

TEST_CASE("part frames: names are one word and never machine") {
  CHECK(PartFrames::refuse_name("cube").empty());
  CHECK(PartFrames::refuse_name("G54").empty());
  CHECK(PartFrames::refuse_name("part_2.b-1").empty());
  for (const char* bad : {"", "machine", "a b", "x/y", "abcdefghijklmnopqrstuvwxy", "ü"}) {
    INFO(bad);
    CHECK_THAT(PartFrames::refuse_name(bad), Catch::Contains("a frame name of 1 to 24"));
  }
}

// Issue 26, 7 and 8: messd's frames file with 1e400 stopped it with nlohmann's text; a name
// such as ../../etc was loaded; a directory was "not valid JSON".
TEST_CASE("part frames: a frames file is refused naming it, for an overflow, a bad name or a directory") {
  const auto dir = temp_dir("refused");
  auto write = [&](const std::string& name, const std::string& text) {
    std::ofstream(dir / name) << text;
    return dir / name;
  };
  const std::string matrix = "[[1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]]";
  auto frame = [&](const std::string& name, const std::string& raw, const std::string& inverse) {
    return "{\"frames\": {\"" + name + "\": {\"raw\": " + raw + ", \"orthonormal\": " + raw + ", \"inverse\": " + inverse + "}}}";
  };
  const auto big = write("big.json", frame("cube", "[[1,0,0,1e400],[0,1,0,0],[0,0,1,0],[0,0,0,1]]", matrix));
  CHECK_THROWS_WITH(PartFrames(big), Catch::StartsWith(big.string() + ": key 'frames.cube.raw[0][3]' holds a number too large"));
  const auto etc = write("etc.json", frame("../../etc", matrix, matrix));
  CHECK_THROWS_WITH(PartFrames(etc), Catch::StartsWith(etc.string() + ": frames.../../etc") &&
                                         Catch::Contains("letters, digits, '_', '-' or '.'"));
  const auto far = write("far.json", frame("far", "[[1,0,0,1e300],[0,1,0,0],[0,0,1,0],[0,0,0,1]]", "[[1,0,0,-1e300],[0,1,0,0],[0,0,1,0],[0,0,0,1]]"));
  CHECK_THROWS_WITH(PartFrames(far), Catch::StartsWith(far.string() + ": frames.far") &&
                                         Catch::Contains("from -1000000 to 1000000 mm"));
  fs::create_directories(dir / "sub");
  CHECK_THROWS_WITH(PartFrames(dir / "sub"), Catch::Contains((dir / "sub").string() + ": is a directory"));
  fs::remove_all(dir);
}
