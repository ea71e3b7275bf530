// ProgramPeer's replies.
#include "program_peer.hpp"

namespace imess::test {
namespace {

std::string with_name(std::string text, const std::string& name) {
  for (auto at = text.find("{NAME}"); at != std::string::npos; at = text.find("{NAME}"))
    text.replace(at, 6, name);
  return text;
}

}  // namespace

ProgramPeer::ProgramPeer(ProgramPeerScript script) {
  FakeDaemonScript fake;
  fake.greeting = {"CurrCor 0.000 0.000 0.000"};
  fake.reply = [state = state_, script](const std::string& line) -> std::vector<std::string> {
    std::lock_guard lock(state->mutex);
    if (state->uploading) {
      if (line != ".") {
        state->lines.push_back(line);
        return {};
      }
      state->uploading = false;
      if (!script.load.empty()) return {with_name(script.load, state->name)};
      return {"Ok Load " + state->name + " Lang gcode Lines " + std::to_string(state->lines.size()) +
              " Blocks 3 Segments 2 Length 20.000 Time 1.234"};
    }
    if (line == "Hello messprog") return {script.hello};
    if (line == "Take") return {script.take};
    if (line.rfind("Upload ", 0) == 0) {
      state->uploading = true;
      state->name = line.substr(7);
      state->lines.clear();
      if (!script.upload.empty()) {
        state->uploading = false;  // refused: what follows is read as commands
        return {with_name(script.upload, state->name)};
      }
      return {"Ok Upload " + state->name + " send the lines, then a line '.'"};
    }
    if (line == "Run" || line == "Run detached") {
      if (script.run.empty()) return {"Ok Run " + state->name};
      std::vector<std::string> out;
      for (const auto& l : script.run) out.push_back(with_name(l, state->name));
      return out;
    }
    if (line == "Pause") return {"Ok Pause"};
    if (line == "Resume") return {"Ok Resume"};
    if (line == "Abort") return {"Ok Abort", "ProgEnd " + state->name + " aborted 2 Abort"};
    return {};
  };
  daemon_ = std::make_unique<FakeDaemon>(std::move(fake));
}

std::string ProgramPeer::uploaded_name() const {
  std::lock_guard lock(state_->mutex);
  return state_->name;
}

std::vector<std::string> ProgramPeer::uploaded_lines() const {
  std::lock_guard lock(state_->mutex);
  return state_->lines;
}

}  // namespace imess::test
