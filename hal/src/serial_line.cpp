// A tty opened raw for a card link: open, check, lock, termios.
#include "imess/hal/serial_line.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace imess::hal {

namespace {
struct BaudSpeed {
  int baud;
  speed_t speed;
};
constexpr BaudSpeed kBauds[] = {{9600, B9600},     {19200, B19200},     {38400, B38400},     {57600, B57600},
                                {115200, B115200}, {230400, B230400},   {460800, B460800},   {500000, B500000},
                                {576000, B576000}, {921600, B921600},   {1000000, B1000000}, {1152000, B1152000},
                                {1500000, B1500000}, {2000000, B2000000}, {3000000, B3000000}, {4000000, B4000000}};

speed_t speed_of(int baud) noexcept {
  for (const auto& b : kBauds)
    if (b.baud == baud) return b.speed;
  return B0;
}

[[noreturn]] void fail(SerialLineError::Kind kind, const std::string& path, const std::string& what) {
  throw SerialLineError(kind, "serial device " + path + ": " + what);
}
}  // namespace

bool serial_baud_supported(int baud) noexcept { return speed_of(baud) != B0; }

const char* serial_bauds_text() noexcept {
  return "9600, 19200, 38400, 57600, 115200, 230400, 460800, 500000, 576000, 921600, 1000000, 1152000, 1500000, "
         "2000000, 3000000, 4000000";
}

int open_serial_line(const std::string& path, int baud) {
  using K = SerialLineError::Kind;
  if (!serial_baud_supported(baud))
    fail(K::BadBaud, path, "baud " + std::to_string(baud) + " is not a rate a serial line can be set to (accepted: " +
                               serial_bauds_text() + ")");
  const int fd = ::open(path.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) {
    const int e = errno;
    if (e == ENOENT || e == ENXIO || e == ENODEV)
      fail(K::Missing, path, "no such device (is the card's adapter plugged in, or messcard running?)");
    if (e == EBUSY) fail(K::Busy, path, "busy: another program holds it");
    if (e == EACCES || e == EPERM)
      fail(K::Failed, path, "permission denied (the user needs the device's group, usually 'dialout')");
    fail(K::Failed, path, std::strerror(e));
  }
  if (!isatty(fd)) {
    ::close(fd);
    fail(K::NotATty, path, "not a serial line (a terminal device such as /dev/ttyUSB0 is needed)");
  }
  if (flock(fd, LOCK_EX | LOCK_NB) != 0) {
    ::close(fd);
    fail(K::Busy, path, "busy: another program (another messd?) has it open");
  }
  termios t{};
  if (tcgetattr(fd, &t) != 0) {
    const int e = errno;
    ::close(fd);
    fail(K::Failed, path, std::string("cannot read its settings: ") + std::strerror(e));
  }
  cfmakeraw(&t);
  t.c_cflag |= CLOCAL | CREAD;
  t.c_cflag &= ~(CSTOPB | PARENB | CRTSCTS);
  t.c_cc[VMIN] = 0;
  t.c_cc[VTIME] = 0;
  cfsetispeed(&t, speed_of(baud));
  cfsetospeed(&t, speed_of(baud));
  if (tcsetattr(fd, TCSANOW, &t) != 0) {
    const int e = errno;
    ::close(fd);
    fail(K::Failed, path, std::string("cannot set raw mode at ") + std::to_string(baud) + " baud: " + std::strerror(e));
  }
  tcflush(fd, TCIOFLUSH);
  return fd;
}

}  // namespace imess::hal
