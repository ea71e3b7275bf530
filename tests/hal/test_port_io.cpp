// Port I/O: the shared simulated port space (two mappings of one file see the same
// registers, 8-bit accesses hit the low byte, stray accesses are counted), and the clear
// errors of real port access when it is denied or the device is missing.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "imess/hal/port_io.hpp"

using namespace imess::hal;

namespace {
std::string temp_path(const std::string& name) {
  return (std::filesystem::temp_directory_path() / ("imess-test-" + std::to_string(getpid()) + "-" + name)).string();
}
std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "(no exception)";
}
}  // namespace

TEST_CASE("two mappings of one port file see the same registers") {
  auto path = temp_path("ports");
  SharedPortSpace owner(path, 0x300, 100);
  SharedPortSpace tool(path);  // what messport does
  CHECK(tool.base() == 0x300);
  CHECK(tool.count() == 100);
  owner.out16(0x306, 0xFFFE);
  CHECK(tool.in16(0x306) == 0xFFFE);
  CHECK(static_cast<std::int16_t>(tool.in16(0x306)) == -2);
  tool.out8(0x306, 0x12);  // 8-bit write: low byte only
  CHECK(owner.in16(0x306) == 0xFF12);
  CHECK(owner.in8(0x306) == 0x12);
  CHECK(owner.in16(0x363) == 0);
  CHECK(owner.errors() == 0);
  std::filesystem::remove(path);
}

TEST_CASE("accesses outside the port space read a floating bus and are counted") {
  SharedPortSpace ports("", 0x300, 100);
  CHECK(ports.in16(0x364) == 0xFFFF);
  CHECK(ports.in8(0x2FF) == 0xFF);
  ports.out16(0x400, 1);
  CHECK(ports.errors() == 3);
}

TEST_CASE("a second simulator on the same port file is refused clearly") {
  auto path = temp_path("ports-locked");
  SharedPortSpace first(path, 0x378, 100);
  auto msg = message_of([&] { SharedPortSpace second(path, 0x378, 100); });
  CHECK(msg.find("in use by another simulator") != std::string::npos);
  std::filesystem::remove(path);
}

TEST_CASE("attaching to a missing or foreign file names the file") {
  auto missing = temp_path("no-such-ports");
  auto msg = message_of([&] { SharedPortSpace s(missing); });
  CHECK(msg.find(missing) != std::string::npos);
  CHECK(msg.find("is messd running") != std::string::npos);
  auto foreign = temp_path("foreign");
  std::ofstream(foreign) << "this is not a port space at all";
  msg = message_of([&] { SharedPortSpace s(foreign); });
  CHECK(msg.find("not an IMESS port space") != std::string::npos);
  std::filesystem::remove(foreign);
}

TEST_CASE("x86 port access: out of ioperm's range, or denied, says what to do") {
  auto msg = message_of([] { X86PortIo io(0x3F0, 0x20); });
  CHECK(msg.find("below 0x400") != std::string::npos);
  // Without CAP_SYS_RAWIO ioperm fails and the message names the cure; with it (root in a
  // privileged container) access is granted and nothing is thrown.
  msg = message_of([] { X86PortIo io(0x378, 3); });
  bool granted = msg == "(no exception)";
  if (!granted) {
    CHECK(msg.find("denied") != std::string::npos);
    CHECK(msg.find("CAP_SYS_RAWIO") != std::string::npos);
  }
}

TEST_CASE("ppdev: a missing device and a file that is no parallel port are named") {
  auto msg = message_of([] { PpdevPortIo io("/dev/parport-imess-missing", 0x378); });
  CHECK(msg.find("/dev/parport-imess-missing") != std::string::npos);
  CHECK(msg.find("modprobe ppdev") != std::string::npos);
  auto plain = temp_path("not-a-port");
  std::ofstream(plain) << "x";
  msg = message_of([&] { PpdevPortIo io(plain, 0x378); });
  CHECK(msg.find("cannot claim") != std::string::npos);
  std::filesystem::remove(plain);
}

TEST_CASE("the port access is chosen by name") {
  PortIoConfig c;
  c.type = "sim";
  CHECK(make_port_io(c)->describe().find("simulated port space 0x300..0x363") != std::string::npos);
  c.type = "isa";
  CHECK(message_of([&] { make_port_io(c); }).find("accepted: sim, x86, ppdev") != std::string::npos);
}

TEST_CASE("messport reads, writes and shows a simulated port unsigned, signed and hex") {
  auto path = temp_path("ports-messport");
  SharedPortSpace space(path, 0x300, 100);
  space.out16(0x306, 0xFFFE);
  auto run = [&](const std::string& args) {
    std::string cmd = std::string(IMESS_BIN_DIR) + "/messport --file " + path + " " + args + " 2>&1";
    FILE* p = popen(cmd.c_str(), "r");
    std::string out;
    char buf[256];
    while (fgets(buf, sizeof buf, p)) out += buf;
    pclose(p);
    return out;
  };
  CHECK(run("read 0x306") == "0x0306  u 65534  s     -2  hex 0xFFFE\n");
  CHECK(run("write 0x301 -300") == "0x0301  u 65236  s   -300  hex 0xFED4\n");
  CHECK(space.in16(0x301) == 0xFED4);
  CHECK(run("--8 read 0x306") == "0x0306  u   254  s     -2  hex 0xFE\n");
  CHECK(run("watch 0x300 2 --times 2 --interval 1") == "0x0300  u     0  s      0  hex 0x0000\n0x0301  u 65236  s   -300  hex 0xFED4\n");
  CHECK(run("read 0x400").find("hit no register") != std::string::npos);
  std::filesystem::remove(path);
}
