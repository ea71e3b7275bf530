// Mechanics: the physical machine behind any simulated controller — its axes with motor
// lag, limit/home switches and encoder index marks, a touch probe against the scene, and
// hand pushes while the drives are free. Machine coordinates, mm (degrees for rotary axes);
// the probe is at the machine's X Y Z (AxisLayout::cartesian) in the scene's world.
#pragma once
#include "imess/hal/motion_backend.hpp"
#include "imess/sim/analog_probe.hpp"
#include "imess/sim/scene.hpp"

namespace imess::sim {

struct SimAxisConfig {
  double travel_min = 0, travel_max = 1000;  // usable travel
  double limit_margin = 5;                   // limit switch closes this far beyond the travel
  double hard_margin = 20;                   // mechanical end stop this far beyond the travel
  int home_direction = -1;                   // the end where the home cam sits
  double home_cam_margin = 2;                // cam closes this far beyond that travel end
  double index_pitch = 5;                    // encoder index marks every pitch from travel_min
  double index_width = 0.04;                 // width of one index pulse
};

struct SimProbeConfig {
  double ball_radius = 2.0;
  double pretravel = 0.0;        // deflection at which the switch triggers
  double overtravel = 8.0;       // deflection the stylus survives
  double hysteresis = 0.0005;    // re-seat this much below the trigger point
  bool normally_closed = false;  // switch opens on contact
  // Trigger: the switch only (above). Analog: the switch as well, and a measured deflection
  // vector every step (analog_reading(); analog_probe.hpp).
  ProbeType type = ProbeType::Trigger;
  AnalogProbeConfig analog{};
};

struct MechanicsConfig {
  hal::AxisLayout layout;  // the axes simulated
  hal::AxisArray<SimAxisConfig> axes{SimAxisConfig{}, SimAxisConfig{},
                                     SimAxisConfig{0, 600, 5, 20, +1, 2, 5, 0.04}};  // Z homes up
  SimProbeConfig probe{};
  hal::AxisVec start = (hal::AxisVec() << 430, 330, 100, 0, 0, 0, 0, 0, 0).finished();  // at power-on
  double motor_time_constant = 0.004;  // s, velocity response of a driven axis
};

class Mechanics final : public hal::SimHooks {
 public:
  Mechanics(MechanicsConfig config, Scene scene);

  // Drive side: a driven axis follows the demanded velocity with the motor lag; a free
  // axis stands still unless pushed by hand.
  void set_driven(int axis, bool driven) noexcept { driven_[axis] = driven; }
  void set_motor_velocity(int axis, double v) noexcept { demand_[axis] = v; }
  // Position drive (a stepper motor, an increment-fed drive): the axis goes to the
  // commanded position within the next step, hard stops still stop it, hands cannot push
  // it. Off by default; takes precedence over set_driven.
  void set_position_driven(int axis, bool on) noexcept { position_driven_[axis] = on; commanded_[axis] = pos_[axis]; }
  void command_position(int axis, double pos) noexcept { commanded_[axis] = pos; }
  bool position_driven(int axis) const noexcept { return position_driven_[axis]; }

  void step(double dt) noexcept;

  struct ProbeEdge {
    bool valid = false;    // an edge happened during the last step
    bool contact = false;  // true: touched, false: re-seated
    hal::AxisVec position = hal::AxisVec::Zero();  // the axes at the edge, exact
  };
  const ProbeEdge& probe_edge() const noexcept { return edge_; }

  const hal::AxisVec& carriage() const noexcept { return pos_; }
  Vec3 ball_centre() const noexcept { return config_.layout.cartesian(pos_); }
  double velocity(int axis) const noexcept { return vel_[axis]; }
  bool tip_contact() const noexcept { return contact_; }
  bool tip_signal() const noexcept { return contact_ != config_.probe.normally_closed; }  // raw switch
  double deflection() const noexcept;
  // The analog probe's reading after the last step (at construction: at the start position);
  // always the default (no contact) with a trigger probe.
  const AnalogReading& analog_reading() const noexcept { return reading_; }
  bool probe_overtravel() const noexcept { return deflection() > config_.probe.overtravel; }
  bool limit_neg(int a) const noexcept;
  bool limit_pos(int a) const noexcept;
  bool home_switch(int a) const noexcept;
  bool index_mark(int a) const noexcept;
  unsigned long hard_stop_hits() const noexcept { return hard_stop_hits_; }
  const MechanicsConfig& config() const noexcept { return config_; }
  const Scene& scene() const noexcept { return scene_; }

  // SimHooks: a hand push, carried out over the next steps while the axes are free.
  void push_by_hand(const Vec3& delta, double speed) noexcept override;
  bool hand_moving() const noexcept { return hand_active_; }

 private:
  double deflection_at(const hal::AxisVec& p) const noexcept;
  void find_edge(const hal::AxisVec& from, const hal::AxisVec& to, bool to_contact) noexcept;

  MechanicsConfig config_;
  Scene scene_;
  hal::AxisVec pos_;
  hal::AxisArray<double> vel_{}, demand_{};
  hal::AxisArray<bool> driven_{};
  hal::AxisArray<bool> position_driven_{};
  hal::AxisArray<double> commanded_{};
  bool contact_ = false;
  ProbeEdge edge_;
  AnalogProbe analog_;
  AnalogReading reading_{};
  hal::AxisVec hand_target_ = hal::AxisVec::Zero();
  double hand_speed_ = 0;
  bool hand_active_ = false;
  unsigned long hard_stop_hits_ = 0;
};

}  // namespace imess::sim
