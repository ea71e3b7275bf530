// MeasuringOperator: drives messd over TCP the way a person measures — GoTo a start point,
// jog toward the surface until the probe touches, take the MeasPt, come back.
#pragma once
#include <catch2/catch.hpp>

#include <Eigen/Core>
#include <optional>
#include <sstream>
#include <string>

#include "daemon_process.hpp"
#include "imess/protocol/messages.hpp"

namespace imess::test {

class MeasuringOperator {
 public:
  explicit MeasuringOperator(LineClient& c) : c_(c) {}

  void go_to(const Eigen::Vector3d& p) {
    if (here_ && (*here_ - p).norm() < 1e-9) return;  // already there: GoTo would not change state
    here_ = p;
    std::ostringstream s;
    s << "GoTo " << p.x() << " " << p.y() << " " << p.z();
    REQUIRE(c_.request(s.str()) == std::optional<std::string>("Ok GoTo"));
    bool idle = c_.until_prefix("State idle", 15.0).has_value();
    if (!idle) {
      c_.send("Status");
      c_.until_prefix("Ok Status", 2.0);
      std::string tail;
      for (std::size_t i = c_.seen().size() > 12 ? c_.seen().size() - 12 : 0; i < c_.seen().size(); ++i) tail += c_.seen()[i] + "\n";
      INFO(s.str() << "\n" << tail);
      REQUIRE(idle);
    }
  }
  Eigen::Vector3d touch(const Eigen::Vector3d& dir) {
    here_.reset();
    Eigen::Vector3d v = dir.normalized() * 50.0;
    std::ostringstream s;
    s << "StartMv " << v.x() << " " << v.y() << " " << v.z();
    REQUIRE(c_.request(s.str()) == std::optional<std::string>("Ok StartMv"));
    auto line = c_.until_prefix("MeasPt ", 15.0);
    REQUIRE(line);
    auto m = imess::protocol::parse_message(*line);
    REQUIRE(std::holds_alternative<imess::protocol::MeasPtMsg>(m));
    auto p = std::get<imess::protocol::MeasPtMsg>(m).p;
    REQUIRE(c_.until_prefix("State idle", 10.0));  // retracted
    return {p.x, p.y, p.z};
  }
  Eigen::Vector3d probe(const Eigen::Vector3d& start, const Eigen::Vector3d& dir) {
    go_to(start);
    Eigen::Vector3d p = touch(dir);
    go_to(start);
    return p;
  }

 private:
  LineClient& c_;
  std::optional<Eigen::Vector3d> here_;
};

}  // namespace imess::test
