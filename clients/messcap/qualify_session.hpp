// messcap qualify, live: takes control of messd, touches the reference sphere by a TouchPlan
// with Probe cycles, and hands messd the qualification (Qualify) once it is computed.
#pragma once

#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "imess/client/endpoint.hpp"
#include "machine_link.hpp"
#include "qualification.hpp"

namespace imess::messcap {

struct Touches {
  std::vector<metrology::ProbedPoint> hits;  // as messd reported them: surface, approach, radius
  Eigen::Vector3d offset;                    // the probe offset they were reported with
  double tip_radius = 0;                     // the TipRadius they were compensated with
};

class QualifySession {
 public:
  // Connects and takes control. Throws MachineError.
  QualifySession(const client::Endpoint& endpoint, std::ostream& log);

  // Reads the probe offset and the tip radius in use, then touches the sphere by plan_touches
  // (moves commanded at the planned ball position less the offset in use). A touch that finds
  // nothing, or a touch on the way, throws MachineError saying the sphere is not where `sphere`
  // says. Leaves the ball above the pole.
  Touches touch(const ReferenceSphere& sphere, const TouchPattern& pattern, double feed);

  // Sends `Qualify radius form dx dy dz` (throws MachineError on Err).
  void qualify(const Qualification& q);

  // Gives up control and closes. Returns the Qualified event messd broadcast, if it came.
  std::optional<std::string> release();

 private:
  void move(const Eigen::Vector3d& ball, double feed);

  MachineLink link_;
  std::ostream& log_;
  Eigen::Vector3d offset_ = Eigen::Vector3d::Zero();
  std::optional<std::string> qualified_;
};

}  // namespace imess::messcap
