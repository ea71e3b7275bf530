// Inspection from the web panel: the plans (*.plan.json) of the programs folder, and a plan run
// by messcap itself — `messcap inspect PLAN 127.0.0.1:PORT --html REPORT`, the program beside
// messd, a client of messd on its MESSD port like any — whose report the panel shows as
// /reports/NAME.html. So the inspection, its control, its probing and its report are messcap's
// own (docs/web.md "Inspection"), not a second implementation in messd or the page.
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>

#include <nlohmann/json.hpp>
#include <spdlog/spdlog.h>

#include "imess/jsontext/strict_json.hpp"
#include "web_shared.hpp"

extern char** environ;

namespace imess::net {

namespace asio = boost::asio;
namespace fs = std::filesystem;

namespace {

constexpr std::string_view kPlanSuffix = ".plan.json";
constexpr const char* kAccepted =
    "accepted: {\"inspect\":\"list\",\"id\":N}, {\"inspect\":\"run\",\"plan\":NAME.plan.json,\"id\":N}";

std::string reply(nlohmann::ordered_json out) { return out.dump(); }

nlohmann::ordered_json head(std::int64_t id) { return {{"type", "Inspect"}, {"id", id}}; }

std::string failed(std::int64_t id, const std::string& why) {
  auto out = head(id);
  out["error"] = why;
  return reply(std::move(out));
}

std::vector<std::string> plans_in(const std::string& folder) {
  std::vector<std::string> out;
  std::error_code ec;
  if (folder.empty()) return out;
  for (const auto& e : fs::directory_iterator(folder, ec)) {
    const std::string name = e.path().filename().string();
    if (name.size() > kPlanSuffix.size() && name.ends_with(kPlanSuffix) && e.is_regular_file(ec)) out.push_back(name);
  }
  std::sort(out.begin(), out.end());
  return out;
}

// A plain file name of the folder's plans: no path, nothing odd.
bool plain_plan_name(const std::string& name) {
  if (!name.ends_with(kPlanSuffix) || name.size() > 200) return false;
  return std::all_of(name.begin(), name.end(), [](unsigned char c) { return std::isalnum(c) || c == '-' || c == '_' || c == '.'; }) &&
         name.find("..") == std::string::npos;
}

std::string messcap_path() {
  std::error_code ec;
  const auto exe = fs::read_symlink("/proc/self/exe", ec);
  return ec ? std::string() : (exe.parent_path() / "messcap").string();
}

// One messcap inspect: its output read to the end, its exit status, then the answer.
class InspectRun : public std::enable_shared_from_this<InspectRun> {
 public:
  InspectRun(asio::any_io_executor ex, std::shared_ptr<WebServer::Shared> shared, std::int64_t id, std::string plan,
             std::function<void(std::string)> answer)
      : out_(ex), err_(ex), timer_(ex), shared_(std::move(shared)), id_(id), plan_(std::move(plan)), answer_(std::move(answer)) {}

  // Starts messcap; false with the answer given when it cannot.
  bool start() {
    const std::string messcap = messcap_path();
    if (messcap.empty() || ::access(messcap.c_str(), X_OK) != 0) {
      answer_(failed(id_, "messcap is not beside messd (" + messcap + "): the inspection is messcap's"));
      return false;
    }
    const std::string stem = plan_.substr(0, plan_.size() - kPlanSuffix.size());
    report_ = stem + ".html";
    const std::string report_file = (fs::path(shared_->reports) / report_).string();
    std::error_code ec;
    fs::remove(report_file, ec);
    const std::string& listen = shared_->config.listen;
    const std::string host = listen.empty() || listen == "0.0.0.0" || listen.find(':') != std::string::npos ? "127.0.0.1" : listen;
    const std::string endpoint = host + ":" + std::to_string(shared_->sessions.port());
    const std::string plan_file = (fs::path(shared_->config.programs.folder) / plan_).string();
    std::vector<std::string> args{messcap, "inspect", plan_file, endpoint, "--html", report_file};
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    int out[2], err[2];
    if (::pipe2(out, O_CLOEXEC) != 0) return spawn_failed();
    if (::pipe2(err, O_CLOEXEC) != 0) {
      ::close(out[0]), ::close(out[1]);
      return spawn_failed();
    }
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, out[1], 1);
    posix_spawn_file_actions_adddup2(&actions, err[1], 2);
    posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
    const int rc = ::posix_spawn(&pid_, messcap.c_str(), &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    ::close(out[1]);
    ::close(err[1]);
    if (rc != 0) {
      ::close(out[0]), ::close(err[0]);
      errno = rc;
      return spawn_failed();
    }
    spdlog::info("web panel: inspection {} by messcap (pid {}) on {}", plan_, pid_, endpoint);
    shared_->inspecting = true;
    out_.assign(out[0]);
    err_.assign(err[0]);
    read(out_, table_);
    read(err_, messages_);
    return true;
  }

 private:
  bool spawn_failed() {
    answer_(failed(id_, std::string("cannot start messcap: ") + std::strerror(errno)));
    return false;
  }

  void read(asio::posix::stream_descriptor& from, std::string& into) {
    from.async_read_some(asio::buffer(chunk_), [self = shared_from_this(), &from, &into](boost::system::error_code ec, std::size_t n) {
      if (ec) {
        if (++self->closed_ == 2) self->reap();
        return;
      }
      if (into.size() < (1u << 20)) into.append(self->chunk_.data(), n);
      self->read(from, into);
    });
  }

  // Both pipes closed: messcap is ending; its status without blocking the io thread.
  void reap() {
    int status = 0;
    const pid_t r = ::waitpid(pid_, &status, WNOHANG);
    if (r == 0) {
      timer_.expires_after(std::chrono::milliseconds(20));
      timer_.async_wait([self = shared_from_this()](boost::system::error_code) { self->reap(); });
      return;
    }
    shared_->inspecting = false;
    auto out = head(id_);
    out["plan"] = plan_;
    out["status"] = r == pid_ && WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    out["table"] = table_;
    out["messages"] = messages_;
    std::error_code ec;
    if (fs::is_regular_file(fs::path(shared_->reports) / report_, ec)) out["report"] = "/reports/" + report_;
    answer_(reply(std::move(out)));
  }

  asio::posix::stream_descriptor out_, err_;
  asio::steady_timer timer_;
  std::shared_ptr<WebServer::Shared> shared_;
  std::int64_t id_;
  std::string plan_;
  std::function<void(std::string)> answer_;
  std::array<char, 4096> chunk_{};
  std::string table_, messages_, report_;
  pid_t pid_ = -1;
  int closed_ = 0;
};

}  // namespace

bool answer_inspect_message(std::string_view message, const std::shared_ptr<WebServer::Shared>& shared, asio::any_io_executor ex,
                            const std::string& observe_reason, std::function<void(std::string)> answer) {
  jsontext::Options options;
  options.max_depth = 1;
  const auto request = jsontext::object_naming(message, {"inspect"}, options);
  if (!request) return false;  // webjson refuses it, saying why
  const nlohmann::json& j = *request;
  std::int64_t id = 0;
  if (const auto it = j.find("id"); it != j.end() && it->is_number_integer()) id = it->get<std::int64_t>();
  for (const auto& [key, v] : j.items())
    if (key != "inspect" && key != "id" && key != "plan") {
      answer(failed(id, "unknown key \"" + key + "\"; " + kAccepted));
      return true;
    }
  const auto& folder = shared->config.programs.folder;
  if (j["inspect"] == "list") {
    auto out = head(id);
    out["plans"] = plans_in(folder);
    answer(reply(std::move(out)));
    return true;
  }
  if (j["inspect"] != "run" || !j.contains("plan") || !j["plan"].is_string()) {
    answer(failed(id, kAccepted));
    return true;
  }
  const std::string plan = j["plan"].get<std::string>();
  if (!observe_reason.empty()) {
    answer(failed(id, "the inspection moves the machine, and " + observe_reason));
    return true;
  }
  if (!plain_plan_name(plan) || !fs::is_regular_file(fs::path(folder) / plan)) {
    answer(failed(id, "no plan '" + plan + "' in the programs folder (" + folder + "); its plans are files NAME.plan.json"));
    return true;
  }
  if (shared->inspecting) {
    answer(failed(id, "an inspection is running; wait for its report"));
    return true;
  }
  std::make_shared<InspectRun>(ex, shared, id, plan, std::move(answer))->start();
  return true;
}

}  // namespace imess::net
