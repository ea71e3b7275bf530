// posix_openpt, grantpt, unlockpt, ptsname; raw mode; the symbolic link replaced atomically.
#include "pty.hpp"

#include <fcntl.h>
#include <stdlib.h>
#include <sys/stat.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>

namespace imess::messcard {

namespace {
[[noreturn]] void fail(const std::string& what) { throw std::runtime_error(what + ": " + std::strerror(errno)); }

void make_raw(int fd) {
  termios t{};
  if (tcgetattr(fd, &t) != 0) fail("reading the pseudo-terminal's settings");
  cfmakeraw(&t);
  t.c_cc[VMIN] = 0;
  t.c_cc[VTIME] = 0;
  if (tcsetattr(fd, TCSANOW, &t) != 0) fail("setting the pseudo-terminal raw");
}
}  // namespace

Pty open_pty(const std::string& link) {
  struct stat st {};
  if (lstat(link.c_str(), &st) == 0 && !S_ISLNK(st.st_mode))
    throw std::runtime_error(link + " exists and is not a symbolic link: not replacing it");
  Pty p;
  p.master = posix_openpt(O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
  if (p.master < 0) fail("posix_openpt");
  if (grantpt(p.master) != 0 || unlockpt(p.master) != 0) fail("grantpt/unlockpt");
  const char* name = ptsname(p.master);
  if (!name) fail("ptsname");
  p.slave_name = name;
  p.slave = ::open(name, O_RDWR | O_NOCTTY | O_CLOEXEC);
  if (p.slave < 0) fail("opening " + p.slave_name);
  make_raw(p.slave);
  const std::string tmp = link + ".messcard-" + std::to_string(getpid());
  ::unlink(tmp.c_str());
  if (symlink(p.slave_name.c_str(), tmp.c_str()) != 0) fail("creating the link " + tmp);
  if (std::rename(tmp.c_str(), link.c_str()) != 0) {
    ::unlink(tmp.c_str());
    fail("making " + link + " point to " + p.slave_name);
  }
  return p;
}

}  // namespace imess::messcard
