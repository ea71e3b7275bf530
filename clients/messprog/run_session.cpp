// messprog run's conversation with messd.
#include "run_session.hpp"

#include "check_report.hpp"
#include "imess/client/hello_caps.hpp"
#include "imess/protocol/messages.hpp"

namespace imess::messprog {
namespace {

namespace p = protocol;

std::string err_text(const p::ErrMsg& e) { return "Err " + std::to_string(e.code) + " " + e.text; }

}  // namespace

RunSession::RunSession(Upload upload, Settings settings) : upload_(std::move(upload)), settings_(std::move(settings)) {}

RunOutput RunSession::start() {
  RunOutput out;
  out.send.push_back("Hello messprog");
  return out;
}

RunOutput RunSession::finish(RunOutput out, int status) {
  phase_ = Phase::Ended;
  asking_ = false;
  out.exit = status;
  return out;
}

RunOutput RunSession::abort(RunOutput out) {
  asking_ = false;
  if (abort_sent_) return out;
  abort_sent_ = true;
  out.send.push_back("Abort");
  out.notes.push_back("messprog: Abort sent; waiting for messd to stop the program");
  return out;
}

std::string RunSession::source_line(int line) const {
  if (line < 1 || static_cast<std::size_t>(line) > upload_.lines.size()) return {};
  return "  " + std::to_string(line) + " | " + upload_.lines[static_cast<std::size_t>(line) - 1];
}

RunOutput RunSession::on_line(std::string_view line) {
  if (phase_ == Phase::Ended) return {};
  const auto message = p::parse_message(line);
  if (std::holds_alternative<p::OkMsg>(message) || std::holds_alternative<p::ErrMsg>(message)) return on_reply(line);
  return on_event(line);
}

RunOutput RunSession::on_reply(std::string_view line) {
  RunOutput out;
  const auto message = p::parse_message(line);
  const auto* ok = std::get_if<p::OkMsg>(&message);
  const auto* err = std::get_if<p::ErrMsg>(&message);
  switch (phase_) {
    case Phase::Greeting:
      if (err) {
        out.errors.push_back("messprog: messd at " + settings_.where + " refused Hello: " + err_text(*err));
        return finish(out, 1);
      }
      if (ok->verb != "Hello") return out;
      if (!client::hello_has_cap(ok->args, "programs")) {
        out.errors.push_back("messprog: messd at " + settings_.where +
                             " does not run programs (its Hello names no 'programs' among its Caps: " +
                             std::string(line) + "); a newer messd is needed");
        return finish(out, 1);
      }
      out.send.push_back("Take");
      phase_ = Phase::Taking;
      return out;
    case Phase::Taking:
      if (err) {
        out.errors.push_back("messprog: cannot take control of the machine: " + err_text(*err));
        return finish(out, 1);
      }
      if (ok->verb != "Take") return out;
      // The lines follow only messd's Ok Upload: were Upload refused (the name, control taken
      // over meanwhile), every program line would reach messd as a command of its own.
      out.send.push_back("Upload " + upload_.name);
      phase_ = Phase::Announcing;
      return out;
    case Phase::Announcing:
      if (err) {
        out.errors.push_back("messprog: messd refused Upload " + upload_.name + ": " + err_text(*err));
        return finish(out, 1);
      }
      if (ok->verb != "Upload") return out;
      out.send = upload_.lines;
      out.send.push_back(".");
      phase_ = Phase::Uploading;
      return out;
    case Phase::Uploading:
      if (err) {
        std::string text = err->text;
        const std::string prefix = "Upload " + upload_.name + ": ";
        if (text.rfind(prefix, 0) == 0) text = text.substr(prefix.size());
        if (text.rfind("line ", 0) != 0) {
          // no line of the program to name (Err 202: another program runs; the size limits):
          // messd's words as they are
          out.errors.push_back("messprog: messd refused " + upload_.name + ": " + err_text(*err));
          return finish(out, 1);
        }
        // "Upload part.nc: line 3:7: kind: ..." → "part.nc:3:7: kind: ..." with the local file's name
        out.errors.push_back("messprog: messd refused " + upload_.name + " (Err " + std::to_string(err->code) + "):");
        out.errors.push_back(located_error(settings_.file, text));
        return finish(out, 1);
      }
      if (ok->verb != "Load") return out;
      if (!ok->args.empty()) upload_.name = ok->args[0];  // the events name the program as messd filed it
      out.notes.push_back("messprog: messd checked " + upload_.name + ": " + load_summary(ok->args));
      out.send.push_back(settings_.detached ? "Run detached" : "Run");
      phase_ = Phase::Starting;
      return out;
    case Phase::Starting:
      if (err) {
        out.errors.push_back("messprog: messd refused to run " + upload_.name + ": " + err_text(*err));
        return finish(out, 1);
      }
      if (ok->verb != "Run") return out;
      out.notes.push_back(std::string("messprog: running ") + upload_.name + (settings_.detached ? " (detached)" : "") +
                          (settings_.interactive ? "; Ctrl-C pauses" : "; Ctrl-C aborts"));
      phase_ = Phase::Running;
      return out;
    case Phase::Running:
      if (err) out.errors.push_back("messprog: messd: " + err_text(*err));  // e.g. a refused Resume
      return out;
    case Phase::Ended:
      return out;
  }
  return out;
}

RunOutput RunSession::on_event(std::string_view line) {
  RunOutput out;
  if (phase_ != Phase::Starting && phase_ != Phase::Running) return out;
  if (auto b = parse_block(line)) {
    if (b->name == upload_.name) out.block = *b;
    return out;
  }
  if (auto pause = parse_prog_pause(line)) {
    if (pause->name != upload_.name) return out;
    const std::string where = "messprog: M0 at line " + std::to_string(pause->line) + ": the machine waits";
    if (settings_.interactive) {
      out.notes.push_back(where);
      out.ask = asking_ = true;
    } else {
      out.notes.push_back(where + "; stdin is not a terminal, so nobody can answer here: Ctrl-C aborts");
    }
    return out;
  }
  if (auto end = parse_prog_end(line)) {
    if (end->name != upload_.name) return out;
    out.end = *end;
    const std::string at = " at line " + std::to_string(end->line);
    if (end->outcome == ProgEndEvent::Outcome::Ok) {
      out.notes.push_back("messprog: " + upload_.name + " ended ok" + at);
      return finish(out, 0);
    }
    out.errors.push_back("messprog: " + upload_.name + " " + outcome_name(end->outcome) + at + ": " + end->text);
    if (auto src = source_line(end->line); !src.empty()) out.errors.push_back(src);
    return finish(out, 1);
  }
  const auto message = p::parse_message(line);
  if (const auto* w = std::get_if<p::WarnMsg>(&message))
    out.errors.push_back("messprog: messd: Warn " + w->name + (w->text.empty() ? "" : " " + w->text));
  else if (const auto* f = std::get_if<p::FaultMsg>(&message))
    out.errors.push_back("messprog: messd: Fault " + f->name + (f->text.empty() ? "" : " " + f->text));
  return out;
}

RunOutput RunSession::interrupt() {
  RunOutput out;
  switch (phase_) {
    case Phase::Greeting:
    case Phase::Taking:
    case Phase::Announcing:
    case Phase::Uploading:
      out.errors.push_back("messprog: interrupted before Run: nothing was started");
      return finish(out, 1);
    case Phase::Starting:
    case Phase::Running:
      if (abort_sent_) {
        out.errors.push_back("messprog: interrupted again; leaving without waiting for ProgEnd" +
                             std::string(settings_.detached ? "" : " (the closed connection stops the program)"));
        return finish(out, 1);
      }
      if (!settings_.interactive || asking_) return abort(out);
      out.send.push_back("Pause");
      out.ask = asking_ = true;
      return out;
    case Phase::Ended:
      return out;
  }
  return out;
}

RunOutput RunSession::terminate() {
  if (phase_ == Phase::Starting || phase_ == Phase::Running) {
    if (!abort_sent_) return abort({});
  }
  RunOutput out;
  if (phase_ == Phase::Ended) return out;
  out.errors.push_back("messprog: terminated");
  return finish(out, 1);
}

RunOutput RunSession::answer(std::string_view text) {
  RunOutput out;
  if (!asking_ || phase_ == Phase::Ended) return out;
  const auto first = text.find_first_not_of(" \t\r\n");
  const char c = first == std::string_view::npos ? '\0' : text[first];
  if (c == 'a' || c == 'A') return abort(out);
  if (c == 'r' || c == 'R') {
    asking_ = false;
    out.send.push_back("Resume");
    out.notes.push_back("messprog: Resume sent");  // and the progress line comes back under it
    return out;
  }
  out.notes.push_back("messprog: answer a (abort the program) or r (resume it)");
  out.ask = true;
  return out;
}

RunOutput RunSession::lost(std::string_view reason) {
  RunOutput out;
  if (phase_ == Phase::Ended) return out;
  std::string text = "messprog: lost the connection to " + settings_.where + " (" + std::string(reason) + ")";
  if (phase_ == Phase::Starting || phase_ == Phase::Running)
    text += settings_.detached ? " while " + upload_.name + " ran; it goes on in messd (detached): 'Program' tells how it stands"
                               : " while " + upload_.name + " ran; messd stops a program whose client goes away "
                                 "(--detached lets it go on)";
  else
    text += " before the program was started";
  out.errors.push_back(text);
  return finish(out, 1);
}

}  // namespace imess::messprog
