// The I++ DME commands that answer at once: session, errors, properties, tools, coordinate
// systems, daemons, queries; the fast queue. GoTo, PtMeas and Home start motion steps
// (ipp_motion.cpp). What each answers: docs/ippdme.md, "Server".
#include <spdlog/spdlog.h>

#include <cmath>

#include "imess/net/ipp_server.hpp"
#include "overloaded.hpp"

namespace imess::net {

using ippdme::ErrorCode;
using ippdme::Item;
using ippdme::Tag;
using ippdme::Value;

namespace {
constexpr int kCoordinateDecimals = 4;  // mm, as X(150.0000)

double degrees_mod_360(double a) {
  const double m = std::fmod(a, 360.0);
  return m < 0 ? m + 360.0 : m;
}
}  // namespace

// X Y Z where the tip stands; R (a rotary table's angle) and Tool.A/B/C (a probe head's) are
// 0: no machine here has a table or a head, and the spec lets a server report them so.
std::string IppServer::position_payload(const std::vector<Item>& items) const {
  const ippdme::Point3 p = tip_here();
  std::vector<Value> values;
  for (Item i : items) {
    const bool axis = i == Item::X || i == Item::Y || i == Item::Z;
    const int c = i == Item::X ? 0 : i == Item::Y ? 1 : 2;
    values.push_back(Value::call(ippdme::item_name(i), {Value::of_fixed(axis ? p[c] : 0.0, kCoordinateDecimals)}));
  }
  return ippdme::format_values(values);
}

void IppServer::change_tool(std::string_view name) {
  if (!tools_.change(name)) return;
  gateway_.set_param(core::ParamId::TipRadius, tools_.active()->radius);
}

void IppServer::get_props(const Tag& tag, const std::vector<std::string>& paths, std::string_view cause) {
  std::vector<Value> values;
  for (const auto& path : paths) {
    auto r = tools_.get(path);
    if (r.error) {
      fail(tag, *r.error, cause);
      return;
    }
    values.push_back(std::move(*r.value));
  }
  send(ippdme::format_data(tag, values));
  finish(tag);
}

void IppServer::set_props(const Tag& tag, const std::vector<ippdme::PropertySetting>& settings, std::string_view cause) {
  for (const auto& s : settings) {
    auto r = tools_.set(s.path, s.value);
    if (r.clamped) {
      send(ippdme::format_error(tag, ErrorCode::ArgumentOutOfRange, cause));  // a warning: the rest still applies
    } else if (r.error) {
      fail(tag, *r.error, cause);
      return;
    }
  }
  finish(tag);
}

bool IppServer::execute(const Pending& p) {
  const Tag& tag = p.tag;
  if (p.refused) {  // a refused line in its turn: its own error, whatever the session's state
    fail(tag, p.refused->first, p.refused->second);
    return true;
  }
  const std::string_view name = ippdme::method_name(p.command);
  const bool session_verb = std::holds_alternative<ippdme::StartSession>(p.command) ||
                            std::holds_alternative<ippdme::EndSession>(p.command);
  if (!in_session_ && !session_verb) {
    fail(tag, ErrorCode::ProtocolError, name);  // outside a session only StartSession and EndSession
    return true;
  }
  if (error_state_ && !session_verb && !std::holds_alternative<ippdme::ClearAllErrors>(p.command) &&
      !std::holds_alternative<ippdme::GetXtdErrStatus>(p.command)) {
    fail(tag, ErrorCode::UseClearAllErrorsToContinue, name);
    return true;
  }
  auto data = [&](std::vector<Value> v) { send(ippdme::format_data(tag, v)); };
  auto flag = [&](std::string_view n, bool b) { data({Value::call(n, {Value::of_integer(b ? 1 : 0)})}); };
  auto done = [&] {
    finish(tag);
    return true;
  };
  return std::visit(
      Overloaded{
          [&](const ippdme::StartSession&) {
            if (in_session_) {
              fail(tag, ErrorCode::ProtocolError, name);
              return true;
            }
            std::string why;
            if (!claim_control(true, why)) {
              spdlog::warn("I++ DME: StartSession refused: {}", why);
              fail(tag, ErrorCode::ErrorProcessingMethod, name);
              return true;
            }
            in_session_ = true;
            error_state_ = false;
            last_error_.reset();
            user_enabled_ = false;
            ptmeas_items_ = {Item::X, Item::Y, Item::Z};
            scan_items_ = ippdme::kDefaultScanReport;
            unknown_density_.reset();
            if (tools_.active()) gateway_.set_param(core::ParamId::TipRadius, tools_.active()->radius);
            return done();
          },
          [&](const ippdme::EndSession&) {
            if (in_session_) end_session(false);
            return done();
          },
          [&](const ippdme::StopDaemon& c) {
            if (!daemon_ || !(daemon_->tag == c.daemon)) {
              fail(tag, ErrorCode::DaemonDoesNotExist, name);
              return true;
            }
            tags_.close(daemon_->tag);
            daemon_.reset();
            return done();
          },
          [&](const ippdme::StopAllDaemons&) {
            if (!daemon_) {
              fail(tag, ErrorCode::NoDaemonsAreActive, name);  // a warning
              return true;
            }
            tags_.close(daemon_->tag);
            daemon_.reset();
            return done();
          },
          [&](const ippdme::GetErrorInfo& c) {
            const auto* info = ippdme::find_error(c.number);
            if (!info) {
              fail(tag, ErrorCode::BadArgument, name);
              return true;
            }
            data({Value::of_string(info->text)});
            return done();
          },
          [&](const ippdme::ClearAllErrors&) {
            if (machine_faulted()) return start_reset(p);  // the machine's error too, when its cause is gone
            error_state_ = false;
            last_error_.reset();
            return done();
          },
          [&](const ippdme::GetProp& c) {
            get_props(tag, c.paths, name);
            return true;
          },
          [&](const ippdme::SetProp& c) {
            set_props(tag, c.settings, name);
            return true;
          },
          [&](const ippdme::EnumProp& c) {
            ErrorCode err{};
            auto entries = tools_.enumerate(c.path, false, err);
            if (!entries) {
              fail(tag, err, name);
              return true;
            }
            for (const auto& [child, kind] : *entries) data({Value::of_string(child), Value::of_string(kind)});
            return done();
          },
          [&](const ippdme::EnumAllProp& c) {
            ErrorCode err{};
            auto entries = tools_.enumerate(c.path, true, err);
            if (!entries) {
              fail(tag, err, name);
              return true;
            }
            for (const auto& [child, kind] : *entries) data({Value::of_string(child), Value::of_string(kind)});
            return done();
          },
          [&](const ippdme::GetDMEVersion&) {
            data({Value::call("DMEVersion", {Value::of_string("1.4")})});
            return done();
          },
          [&](const ippdme::Home&) { return start_home(p); },
          [&](const ippdme::IsHomed&) {
            flag("IsHomed", gateway_.snapshot().referenced);  // the machine knows where it is
            return done();
          },
          [&](const ippdme::EnableUser&) {
            user_enabled_ = true;
            release_control();  // the jog panel may take it
            return done();
          },
          [&](const ippdme::DisableUser&) {
            std::string why;
            if (!claim_control(false, why)) {
              spdlog::warn("I++ DME: DisableUser: {}", why);
              fail(tag, ErrorCode::ErrorProcessingMethod, name);
              return true;
            }
            user_enabled_ = false;
            return done();
          },
          [&](const ippdme::IsUserEnabled&) {
            flag("IsUserEnabled", user_enabled_);
            return done();
          },
          [&](const ippdme::OnPtMeasReport& c) {
            ptmeas_items_ = c.items;
            return done();
          },
          [&](const ippdme::GetMachineClass&) {
            data({Value::call("GetMachineClass", {Value::of_word("CartCMM")})});
            return done();
          },
          [&](const ippdme::GetXtdErrStatus&) {
            flag("IsHomed", gateway_.snapshot().referenced);
            flag("IsUserEnabled", user_enabled_);
            if (error_state_ && last_error_) send(ippdme::format_error(tag, last_error_->first, last_error_->second));
            if (machine_faulted()) send(ippdme::format_error(tag, ErrorCode::MachineInErrorState, "Machine"));
            return done();
          },
          [&](const ippdme::Get& c) {
            send(ippdme::format_data(tag, position_payload(c.items)));
            return done();
          },
          [&](const ippdme::GoTo& c) { return start_goto(p, c); },
          [&](const ippdme::PtMeas& c) { return start_ptmeas(p, c); },
          [&](const ippdme::EnumTools&) {
            for (const auto& n : tools_.names()) data({Value::of_string(n)});
            return done();
          },
          [&](const ippdme::ChangeTool& c) {
            if (!tools_.exists(c.name)) {
              tools_.change(c.name);  // UnDefTool: the state after a failed change
              fail(tag, ErrorCode::ToolNotFound, name);
              return true;
            }
            change_tool(c.name);
            return done();
          },
          [&](const ippdme::SetTool& c) {
            if (!tools_.exists(c.name)) {
              fail(tag, ErrorCode::ToolNotFound, name);
              return true;
            }
            change_tool(c.name);
            return done();
          },
          [&](const ippdme::FindTool& c) {
            if (!tools_.find_tool(c.name)) {
              fail(tag, ErrorCode::ToolNotFound, name);
              return true;
            }
            return done();
          },
          [&](const ippdme::GetChangeToolAction& c) {
            if (!tools_.exists(c.name)) {
              fail(tag, ErrorCode::ToolNotFound, name);
              return true;
            }
            const ippdme::Point3 at = tip_here();  // a switch in place: the tip stays where it stands
            data({Value::call("ChangeToolAction", {Value::of_word("Switch"), Value::call("X", {Value::of_fixed(at[0], kCoordinateDecimals)}),
                                                   Value::call("Y", {Value::of_fixed(at[1], kCoordinateDecimals)}),
                                                   Value::call("Z", {Value::of_fixed(at[2], kCoordinateDecimals)})})});
            return done();
          },
          [&](const ippdme::SetCoordSystem& c) {
            csy_.select(c.csy);
            return done();
          },
          [&](const ippdme::GetCoordSystem&) {
            data({Value::call("CoordSystem", {Value::of_word(ippdme::coord_system_name(csy_.current()))})});
            return done();
          },
          [&](const ippdme::SetCsyTransformation& c) {
            auto t = c.transform;
            t.psi = degrees_mod_360(t.psi);
            t.phi = degrees_mod_360(t.phi);
            // The parser bounds the offsets (±1e6 mm); a chain that still gives no usable
            // PartCsy frame is refused as a bad argument and changes nothing.
            const ippdme::CsyChain before = csy_;
            csy_.set(c.csy, t);
            if (c.csy == ippdme::CsyTarget::PartCsy && !store_part_csy()) {
              csy_ = before;
              fail(tag, ErrorCode::BadArgument, name);
              return true;
            }
            return done();
          },
          [&](const ippdme::GetCsyTransformation& c) {
            const auto& t = csy_.get(c.csy);
            data({Value::call("GetCsyTransformation", {Value::of_number(t.x0), Value::of_number(t.y0), Value::of_number(t.z0),
                                                       Value::of_number(t.theta), Value::of_number(t.psi), Value::of_number(t.phi)})});
            return done();
          },
          [&](const ippdme::OnScanReport& c) {
            scan_items_ = c.items;
            return done();
          },
          // Hints only let a server slow down where it must; the contact control holds the
          // deflection whatever the part's deviation within its reach (docs/ippdme.md).
          [&](const ippdme::ScanOnCircleHint&) { return done(); },
          [&](const ippdme::ScanOnLineHint&) { return done(); },
          [&](const ippdme::ScanUnknownHint&) { return done(); },
          [&](const ippdme::ScanUnknownDensity& c) {
            if (c.dis) unknown_density_ = *c.dis;
            return done();
          },
          [&](const ippdme::ScanOnLine& c) { return start_scan_line(p, c); },
          [&](const ippdme::ScanOnCircle& c) {
            return start_scan_circle(p, c.center, c.start, c.normal, c.delta, c.sfa, c.step, 0);
          },
          [&](const ippdme::ScanOnHelix& c) {
            return start_scan_circle(p, c.center, c.start, c.normal, c.delta, c.sfa, c.step, c.pitch);
          },
          [&](const ippdme::ScanInPlaneEndIsSphere& c) { return start_contour(p, c); },
          [&](const ippdme::ScanInPlaneEndIsPlane& c) { return start_contour(p, c); },
          [&](const ippdme::ScanInPlaneEndIsCyl& c) { return start_contour(p, c); },
          [&](const ippdme::ScanInCylEndIsSphere& c) { return start_contour(p, c); },
          [&](const ippdme::ScanInCylEndIsPlane& c) { return start_contour(p, c); },
          [&](const auto&) {  // a fast-queue method: the parser sends none here (its tag is an event tag)
            fail(tag, ErrorCode::IllegalTag, name);
            return true;
          },
      },
      p.command);
}

void IppServer::execute_fast(const Pending& p) {
  const Tag& tag = p.tag;
  if (p.refused) {
    fail(tag, p.refused->first, p.refused->second);
    return;
  }
  const std::string_view name = ippdme::method_name(p.command);
  if (!in_session_) {
    fail(tag, ErrorCode::ProtocolError, name);
    return;
  }
  if (std::holds_alternative<ippdme::AbortE>(p.command)) {
    // Stop at once; the running command 0006, the queued ones 0006, then AbortE's `%`;
    // afterwards only ClearAllErrors (IPPDME.md §8). Daemons go on.
    const bool running = running_ && !queue_.empty();
    std::optional<Pending> was;
    if (running) was = queue_.front();
    step_ = Step::None;
    gateway_.stop("AbortE");
    rest_.reset();
    if (was) {
      answer_aborted(*was);
      queue_.pop_front();
      running_ = false;
    }
    abort_queued();
    finish(tag);
    if (!error_state_) last_error_ = std::pair(ErrorCode::TransactionAborted, std::string(name));
    error_state_ = true;
    pump();
    return;
  }
  if (std::holds_alternative<ippdme::GetErrStatusE>(p.command)) {
    send(ippdme::format_data(tag, {Value::call("ErrStatus", {Value::of_integer(error_state_ ? 1 : 0)})}));
    finish(tag);
    return;
  }
  if (error_state_) {
    fail(tag, ErrorCode::UseClearAllErrorsToContinue, name);
    return;
  }
  if (const auto* c = std::get_if<ippdme::GetPropE>(&p.command)) {
    get_props(tag, c->paths, name);
  } else if (const auto* s = std::get_if<ippdme::SetPropE>(&p.command)) {
    set_props(tag, s->settings, name);
  } else if (const auto* m = std::get_if<ippdme::OnMoveReportE>(&p.command)) {
    if (daemon_) {
      fail(tag, ErrorCode::DaemonAlreadyExists, name);
      return;
    }
    std::vector<Item> items = m->items;
    // At most 10 reports a second (Time below 0.1 s is read as 0.1).
    daemon_ = MoveDaemon{tag, m->time ? std::optional(std::max(*m->time, 0.1)) : std::nullopt, m->dis, std::move(items), {}, {}};
    send(ippdme::format_done(tag));  // the tag stays open: the daemon's lines carry it
    tick();
  } else {
    fail(tag, ErrorCode::IllegalTag, name);
  }
}

}  // namespace imess::net
