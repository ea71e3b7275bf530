// I++ DME's PartCsy is the controller's active part frame (docs/ippdme.md, "Coordinate
// systems"): a SetCsyTransformation(PartCsy, ...) stores the frame "PartCsy" and makes it
// active; UseFrame, SetFrame or Align on the MESSD port move PartCsy with them.
#include <Eigen/Geometry>
#include <optional>

#include "imess/net/ipp_server.hpp"

namespace imess::net {
namespace {

Eigen::Vector3d vec(const ippdme::Point3& p) { return {p[0], p[1], p[2]}; }
ippdme::Point3 pt(const Eigen::Vector3d& v) { return {v[0], v[1], v[2]}; }

}  // namespace

bool IppServer::store_part_csy() {
  ippdme::CsyChain chain = csy_;
  chain.select(ippdme::CoordSystem::PartCsy);
  Eigen::Matrix3d r;
  for (int i = 0; i < 3; ++i) r.col(i) = vec(chain.vector_to_machine(pt(Eigen::Vector3d::Unit(i))));
  const Eigen::Vector3d origin = vec(chain.to_machine({0, 0, 0}));
  // Within the bound every stored frame keeps (the file is refused at start beyond it).
  if (!r.allFinite() || !(origin.cwiseAbs().maxCoeff() <= kMaxFrameOrigin)) return false;
  std::optional<metrology::Frame> frame;
  try {
    frame.emplace(r, origin, 1e-6);
  } catch (const metrology::FrameError&) {
    return false;
  }
  own_part_csy_ = true;
  frames_.keep("PartCsy", *frame);
  frames_.changed();
  own_part_csy_ = false;
  return true;
}

void IppServer::part_frame_changed() {
  if (own_part_csy_) return;  // it is this session's own PartCsy: kept as the session gave it
  // The link from MoveableMachineCsy to PartCsy that puts the active frame's origin and axes
  // where they are in machine coordinates: q -> F^-1(parent(q)).
  const metrology::Frame& f = frames_.active_frame();
  ippdme::CsyChain parent = csy_;
  parent.select(ippdme::CoordSystem::MoveableMachineCsy);
  auto link = [&](const Eigen::Vector3d& q) { return f.point_from_parent(vec(parent.to_machine(pt(q)))); };
  const Eigen::Vector3d o = link(Eigen::Vector3d::Zero());
  double r[3][3];
  for (int j = 0; j < 3; ++j) {
    const Eigen::Vector3d col = link(Eigen::Vector3d::Unit(j)) - o;
    for (int i = 0; i < 3; ++i) r[i][j] = col[i];
  }
  csy_.set(ippdme::CsyTarget::PartCsy, ippdme::csy_transformation(r, pt(o)));
}

}  // namespace imess::net
