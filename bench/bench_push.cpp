// bench_push: how fast events leave messd. Starts messd (--no-rt, port 0), connects N
// clients, and measures ForcePt -> MeasPt at the last client, and the CurrCor rate the
// last client receives at ReportHz 100 while the owner jogs. Prints figures; asserts nothing.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <memory>
#include <random>
#include <thread>
#include <string>
#include <vector>

#include "daemon_process.hpp"

using namespace imess::test;
using Clock = std::chrono::steady_clock;

namespace {
double percentile(std::vector<double> v, double p) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0 : v[static_cast<std::size_t>(p * static_cast<double>(v.size() - 1))];
}

void run(int clients, int requests, double jog_s) {
  const std::string config = "/tmp/bench-push-" + std::to_string(getpid()) + ".json";
  std::ofstream(config) << R"({"server": {"max_clients": )" << clients + 20 << "}}";
  DaemonProcess messd({"--config", config});
  std::vector<std::unique_ptr<LineClient>> all;
  for (int i = 0; i < clients; ++i) all.push_back(std::make_unique<LineClient>(messd.port()));
  LineClient& owner = *all.front();
  LineClient& last = *all.back();
  for (auto& c : all) c->until_prefix("CurrCor");  // each got its position on connect
  owner.request("Take");

  std::vector<double> ms;
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> phase_us(0, 2000);
  for (int i = 0; i < requests; ++i) {
    // At a random moment: sent right after a MeasPt, a request would always wait one whole
    // 1 ms loop cycle before the loop takes it.
    std::this_thread::sleep_for(std::chrono::microseconds(phase_us(rng)));
    auto t0 = Clock::now();
    owner.send("ForcePt");
    if (!last.until_prefix("MeasPt")) {
      std::printf("no MeasPt at the last client\n");
      break;
    }
    ms.push_back(std::chrono::duration<double, std::milli>(Clock::now() - t0).count());
    owner.until_prefix("Ok ForcePt");
  }
  std::printf("%4d clients: ForcePt -> MeasPt at the last client, %zu requests: p50 %.2f ms  p99 %.2f ms  max %.2f ms\n",
              clients, ms.size(), percentile(ms, 0.5), percentile(ms, 0.99), percentile(ms, 1.0));

  owner.request("Set ReportHz 100");
  owner.request("StartMv 5 0 0");
  last.until_prefix("CurrCor", 2.0);  // moving
  int lines = 0;
  auto start = Clock::now();
  auto end = start + std::chrono::duration<double>(jog_s);
  while (Clock::now() < end) {
    double left = std::chrono::duration<double>(end - Clock::now()).count();
    if (auto l = last.next(left); l && l->rfind("CurrCor", 0) == 0) ++lines;
  }
  owner.request("StopMv");
  std::printf("%4d clients: CurrCor at ReportHz 100 while jogging: %.1f lines/s at the last client\n", clients,
              lines / jog_s);
  std::remove(config.c_str());
}
}  // namespace

int main(int argc, char** argv) {
  int requests = argc > 1 ? std::atoi(argv[1]) : 200;
  for (int n : {1, 100, 200}) run(n, requests, 3.0);
}
