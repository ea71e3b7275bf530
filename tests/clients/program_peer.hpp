// ProgramPeer: a FakeDaemon script that answers a program client the way docs/protocol.md
// says messd does — Hello (with or without the `programs` capability), Take, Upload <name>
// (Ok Upload) up to "." (then the Load reply), Run (then its scripted events), Pause, Resume
// and Abort (ProgEnd aborted). What the client uploaded is kept for the test.
#pragma once
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "fake_daemon.hpp"

namespace imess::test {

struct ProgramPeerScript {
  std::string hello = "Ok Hello IMESS 1 messd 0.1.0 Caps jog goto home probe hand stats journal queue programs sim";
  std::string take = "Ok Take";
  // The reply to "Upload <name>" when it is refused ({NAME} replaced); empty: Ok Upload.
  std::string upload;
  // After ".": {NAME} is replaced by the uploaded name. Empty: the Ok Load reply below.
  std::string load;
  // After Run / Run detached, in order ({NAME} replaced). Empty: Ok Run and nothing more.
  std::vector<std::string> run;
};

class ProgramPeer {
 public:
  explicit ProgramPeer(ProgramPeerScript script = {});

  FakeDaemon& daemon() { return *daemon_; }
  std::string address() const { return daemon_->address(); }
  std::string uploaded_name() const;
  std::vector<std::string> uploaded_lines() const;  // between "Upload <name>" and "."

 private:
  struct State {
    std::mutex mutex;
    bool uploading = false;
    std::string name;
    std::vector<std::string> lines;
  };
  std::shared_ptr<State> state_ = std::make_shared<State>();
  std::unique_ptr<FakeDaemon> daemon_;
};

}  // namespace imess::test
