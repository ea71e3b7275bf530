// Named frames as JSON: round trip (exact), file save/load, error messages naming the key.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include <Eigen/Geometry>

#include "imess/metrology/frame_store.hpp"

using namespace imess::metrology;

namespace {

Eigen::Matrix4d raw_frame(double angle, const Eigen::Vector3d& t, double noise) {
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.topLeftCorner<3, 3>() = Eigen::AngleAxisd(angle, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  m(0, 1) += noise;  // as typed with a few decimals
  m.topRightCorner<3, 1>() = t;
  return m;
}

const char* kGood = R"({
  "frames": {
    "design": {
      "raw":         [[-1, 0, 0, 10], [0, -1, 0, 20], [0, 0, 1, 30], [0, 0, 0, 1]],
      "orthonormal": [[-1, 0, 0, 10], [0, -1, 0, 20], [0, 0, 1, 30], [0, 0, 0, 1]],
      "inverse":     [[-1, 0, 0, 10], [0, -1, 0, 20], [0, 0, 1, -30], [0, 0, 0, 1]]
    }
  }
})";

}  // namespace

TEST_CASE("frame store keeps raw and orthonormalised matrices and round-trips exactly", "[frames][json]") {
  FrameStore store;
  store.set("G54_design", raw_frame(0.7, {100.5, -20.25, 3.0}, 2e-5));
  store.set("table", raw_frame(-2.1, {0, 0, 450}, 0.0));
  REQUIRE(store.size() == 2);
  CHECK(store.find("G54_design")->raw(0, 3) == 100.5);  // row-major: translation in column 3
  CHECK(Frame::rotation_error(store.get("G54_design").rotation()) < 1e-14);

  const std::string text = to_json(store);
  CHECK_THAT(text, Catch::Contains("\"orthonormal\"") && Catch::Contains("\"inverse\"") && Catch::Contains("\"raw\""));
  const FrameStore back = parse_frame_store(text, "mem");
  REQUIRE(back.names() == store.names());
  for (const auto& name : store.names()) {
    CHECK((back.find(name)->raw - store.find(name)->raw).cwiseAbs().maxCoeff() == 0.0);
    CHECK((back.get(name).matrix() - store.get(name).matrix()).cwiseAbs().maxCoeff() == 0.0);
  }

  const auto dir = std::filesystem::temp_directory_path() / "imess_test_frame_store";
  std::filesystem::create_directories(dir);
  const auto path = dir / "frames.json";
  save_frame_store(path, store);
  const FrameStore loaded = load_frame_store(path);
  CHECK(loaded.names() == store.names());
  CHECK_FALSE(std::filesystem::exists(dir / "frames.json.tmp"));
  std::filesystem::remove_all(dir);

  CHECK_THROWS_WITH(store.get("nope"), Catch::Contains("no frame named 'nope'") &&
                                          Catch::Contains("the store holds: " + store.names().front()));
  CHECK(store.erase("table"));
  CHECK_FALSE(store.erase("table"));
}

TEST_CASE("frame store parses a hand-written file and validates it", "[frames][json]") {
  const FrameStore s = parse_frame_store(kGood, "frames.json");
  const Frame& f = s.get("design");
  CHECK((f.point_to_parent(Eigen::Vector3d(1, 1, 1)) - Eigen::Vector3d(9, 19, 31)).norm() == 0.0);
}

TEST_CASE("frame store errors name the file and the key", "[frames][json][errors]") {
  auto with = [](const std::string& from, const std::string& to) {
    std::string t = kGood;
    t.replace(t.find(from), from.size(), to);
    return t;
  };
  CHECK_THROWS_WITH(parse_frame_store("{", "f.json"), Catch::Contains("f.json") && Catch::Contains("not valid JSON"));
  CHECK_THROWS_WITH(parse_frame_store("{}", "f.json"), Catch::Contains("f.json: frames"));
  CHECK_THROWS_WITH(parse_frame_store(with("\"inverse\"", "\"inv\""), "f.json"),
                    Catch::Contains("frames.design.inverse") && Catch::Contains("missing"));
  CHECK_THROWS_WITH(parse_frame_store(with("[0, -1, 0, 20], [0, 0, 1, 30], [0, 0, 0, 1]],\n      \"orthonormal\"",
                                           "[0, -1, 0, 20], [0, 0, 1], [0, 0, 0, 1]],\n      \"orthonormal\""), "f.json"),
                    Catch::Contains("frames.design.raw[2]"));
  CHECK_THROWS_WITH(parse_frame_store(with("[[-1, 0, 0, 10]", "[[-1, \"x\", 0, 10]"), "f.json"),
                    Catch::Contains("frames.design.raw[0][1]") && Catch::Contains("expected a number"));
  CHECK_THROWS_WITH(parse_frame_store(with("[0, 0, 1, -30]", "[0, 0, 1, 30]"), "f.json"),
                    Catch::Contains("frames.design.inverse") && Catch::Contains("not the inverse"));
  // orthonormal no longer matches the raw matrix
  CHECK_THROWS_WITH(parse_frame_store(with("\"orthonormal\": [[-1, 0, 0, 10]", "\"orthonormal\": [[-1, 0, 0, 11]"), "f.json"),
                    Catch::Contains("frames.design.orthonormal"));
  // a reflection
  CHECK_THROWS_WITH(parse_frame_store(with("[0, 0, 1, 30], [0, 0, 0, 1]],\n      \"orthonormal\"",
                                           "[0, 0, -1, 30], [0, 0, 0, 1]],\n      \"orthonormal\""), "f.json"),
                    Catch::Contains("frames.design.raw") && Catch::Contains("reflection"));
  CHECK_THROWS_WITH(load_frame_store("/nonexistent/dir/frames.json"), Catch::Contains("cannot open"));
  FrameStore s;
  CHECK_THROWS_WITH(s.set("bad", Eigen::Matrix4d::Zero()), Catch::Contains("frame 'bad'"));
}

// Issue 26, 7 and 8: a number beyond a double escaped as nlohmann's out_of_range (and stopped
// messd); a name such as ../../etc was taken; a directory was "not valid JSON".
TEST_CASE("frame store refuses an overflowing number, a bad name and a directory, naming each", "[frames][json][errors]") {
  auto with = [](const std::string& from, const std::string& to) {
    std::string t = kGood;
    t.replace(t.find(from), from.size(), to);
    return t;
  };
  CHECK_THROWS_AS(parse_frame_store(with("[[-1, 0, 0, 10]", "[[-1, 1e400, 0, 10]"), "f.json"), FrameError);
  CHECK_THROWS_WITH(parse_frame_store(with("[[-1, 0, 0, 10]", "[[-1, 1e400, 0, 10]"), "f.json"),
                    Catch::StartsWith("f.json: key 'frames.design.raw[0][1]' holds a number too large for a double ('1e400')") &&
                        Catch::Contains("are accepted"));
  for (const char* bad : {"../../etc", "a b", "x/y", "", "caf\xc3\xa9"}) {
    INFO(bad);
    CHECK_THROWS_WITH(parse_frame_store(with("\"design\"", std::string("\"") + bad + "\""), "f.json"),
                      Catch::StartsWith("f.json: frames.") && Catch::Contains("letters, digits, '_', '-' or '.'"));
  }
  CHECK(parse_frame_store(with("\"design\"", "\"G54_part-2.b\""), "f.json").find("G54_part-2.b"));
  FrameStore s;
  CHECK_THROWS_WITH(s.set("../../etc", Eigen::Matrix4d::Identity()), Catch::Contains("letters, digits, '_', '-' or '.'"));
  const auto dir = std::filesystem::temp_directory_path() / "imess_test_frame_store_dir";
  std::filesystem::create_directories(dir);
  CHECK_THROWS_WITH(load_frame_store(dir), Catch::Contains(dir.string() + ": is a directory") && !Catch::Contains("not valid JSON"));
  std::filesystem::remove_all(dir);
}
