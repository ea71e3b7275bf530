#!/usr/bin/env bash
# The Debian package: packs the build tree it is given with cpack (as scripts/package does, from
# the programs already built: seconds, no second build), unpacks it with dpkg-deb and checks what
# a controller box gets — every program, every man page (gzip -9n), /etc/imess/messd.json as a
# conffile that the unpacked messd loads and serves, the systemd unit (systemd-analyze verify
# where it works) and the udev rule, the control fields (Depends from dpkg-shlibdeps) —,
# installs, upgrades, removes and purges it with dpkg in an empty root (as root), and runs
# lintian where installed (errors fail, warnings are shown).
# Usage: test_deb.sh BUILD_DIR VERSION PROGRAM...   Exit 77 (skipped) without dpkg-deb or cpack.
set -uo pipefail
build=$1 version=$2
shift 2
programs=("$@")
for tool in dpkg-deb cpack; do
  command -v $tool >/dev/null || { echo "$tool not found: skipped"; exit 77; }
done
command -v dpkg-shlibdeps >/dev/null || { echo "FAIL: dpkg-shlibdeps not found (Debian package dpkg-dev; scripts/deps.sh installs it)"; exit 1; }

tmp=$(mktemp -d)
messd_pid=""
cleanup() { [ -n "$messd_pid" ] && kill -KILL "$messd_pid" 2>/dev/null; rm -rf "$tmp"; }
trap cleanup EXIT
status=0
fail() { echo "FAIL: $*"; status=1; }

start=$(date +%s%N)
if ! cpack -G DEB --config "$build/CPackConfig.cmake" -B "$tmp/out" >"$tmp/cpack.log" 2>&1; then
  cat "$tmp/cpack.log"
  echo "FAIL: cpack"
  exit 1
fi
deb=$(ls "$tmp"/out/*.deb 2>/dev/null | head -1)
[ -n "$deb" ] || { cat "$tmp/cpack.log"; echo "FAIL: cpack made no .deb"; exit 1; }
echo "packed $(basename "$deb"): $(du -k "$deb" | cut -f1) KiB in $((($(date +%s%N) - start) / 1000000)) ms"

root=$tmp/root
dpkg-deb -x "$deb" "$root" || { echo "FAIL: dpkg-deb -x"; exit 1; }
dpkg-deb -e "$deb" "$tmp/control" || { echo "FAIL: dpkg-deb -e"; exit 1; }

# Control fields.
field() { sed -n "s/^$1: //p" "$tmp/control/control"; }
[ "$(field Package)" = imess ] || fail "Package is '$(field Package)', not imess"
[ "$(field Version)" = "$version" ] || fail "Version is '$(field Version)', not the project's $version"
[ "$(field Architecture)" = "$(dpkg --print-architecture)" ] || fail "Architecture is '$(field Architecture)'"
grep -q 'libc6' <<<"$(field Depends)" || fail "Depends '$(field Depends)' names no libc6: dpkg-shlibdeps did not run"
[ "$(field Recommends)" = libjs-three ] || fail "Recommends is '$(field Recommends)', not libjs-three (the web panel's 3-D view)"
for f in Maintainer Section Description; do [ -n "$(field $f)" ] || fail "no $f field"; done
grep -qx '/etc/imess/messd.json' "$tmp/control/conffiles" 2>/dev/null || fail "/etc/imess/messd.json is not a conffile"
for s in postinst postrm; do [ -x "$tmp/control/$s" ] || fail "no executable $s"; done

# Programs and man pages.
for p in "${programs[@]}"; do
  [ -x "$root/usr/bin/$p" ] || fail "usr/bin/$p missing"
  page=$(ls "$root"/usr/share/man/man[18]/"$p".[18].gz 2>/dev/null | head -1)
  if [ -z "$page" ]; then fail "no man page $p.1.gz or $p.8.gz"
  elif ! gzip -t "$page" 2>/dev/null; then fail "$page is not gzip"
  else
    # gzip -n: the header (RFC 1952) holds no file name (FLG bit 3) and no time (MTIME 0).
    read -r -a h <<<"$(od -An -tu1 -N8 "$page")"
    (( (h[3] & 8) == 0 && h[4] + h[5] + h[6] + h[7] == 0 )) || fail "$(basename "$page") keeps a name or a time (not gzip -n)"
  fi
done
[ -x "$root/usr/bin/messd" ] && [ -e "$root/usr/share/man/man8/messd.8.gz" ] || fail "messd's page is not in section 8"
extra=$(comm -13 <(printf '%s\n' "${programs[@]}" | sort) <(ls "$root/usr/bin" | sort))
[ -z "$extra" ] || fail "usr/bin holds programs the package should not: $extra"
[ -n "$(find "$root" -name '*.debug' -o -path '*/include/*' | head -1)" ] && fail "debug files or headers in the package"
v=$("$root/usr/bin/messd" -v 2>&1)
grep -q "^messd $version " <<<"$v" || fail "the packed messd says '$v', not version $version"

# The configuration: a conffile messd loads; it serves on it until stopped.
conf=$root/etc/imess/messd.json
if [ ! -f "$conf" ]; then fail "etc/imess/messd.json missing"
else
  "$root/usr/bin/messd" --config "$conf" --port 0 --ippdme-port 0 --journal "$tmp/journal" \
      --frames "$tmp/frames.json" --no-rt >"$tmp/messd.out" 2>"$tmp/messd.err" &
  messd_pid=$!
  for _ in $(seq 1 300); do
    grep -q "OK, listening" "$tmp/messd.out" && break
    kill -0 "$messd_pid" 2>/dev/null || break
    sleep 0.1
  done
  if grep -q "OK, listening" "$tmp/messd.out"; then
    kill -TERM "$messd_pid"; wait "$messd_pid"; rc=$?
    [ $rc -eq 0 ] || fail "messd on etc/imess/messd.json exited $rc after SIGTERM"
    echo "etc/imess/messd.json: messd loads it and serves ($(grep -o 'controller: .*' "$tmp/messd.err" | head -1))"
  else
    fail "messd does not start on etc/imess/messd.json:"; cat "$tmp/messd.out" "$tmp/messd.err"
  fi
  messd_pid=""
  grep -q '"folder": "/usr/share/imess/examples/programs"' "$conf" || fail "etc/imess/messd.json's programs folder is not /usr/share/imess/examples/programs"
  [ -n "$(ls "$root/usr/share/imess/examples/programs" 2>/dev/null)" ] || fail "no example programs in usr/share/imess/examples/programs"
  [ -f "$root/usr/share/imess/config/sim-servo-card.json" ] || fail "the shipped configurations are not in usr/share/imess/config"
fi

# The unit and the udev rule.
unit=$root/lib/systemd/system/messd.service
rule=$root/lib/udev/rules.d/99-imess-card.rules
[ -f "$unit" ] || fail "lib/systemd/system/messd.service missing"
grep -q '^ExecStart=/usr/bin/messd --config /etc/imess/messd.json ' "$unit" || fail "the unit does not start /usr/bin/messd on /etc/imess/messd.json"
grep -q '^SupplementaryGroups=.*dialout' "$unit" || fail "the unit's user is not in dialout, the group of the card's port"
[ -f "$rule" ] || fail "lib/udev/rules.d/99-imess-card.rules missing"
grep -q '^ExecStart=/usr/bin/messmqtt --config /etc/imess/messd.json$' "$root/lib/systemd/system/messmqtt.service" \
  || fail "lib/systemd/system/messmqtt.service missing, or it does not start /usr/bin/messmqtt on /etc/imess/messd.json"
grep -q '^SUBSYSTEM=="tty".*SYMLINK+="ttyIMESS0".*GROUP="dialout".*MODE="0660"' "$rule" || fail "the udev rule does not make ttyIMESS0 for dialout, 0660"
if command -v udevadm >/dev/null && udevadm verify --help >/dev/null 2>&1; then
  udevadm verify "$rule" || fail "udevadm verify $rule"
fi
if ! command -v systemd-analyze >/dev/null; then
  echo "systemd-analyze not found: the unit is not verified"
elif [ -f "$unit" ]; then
  # The unit as installed, pointing at the unpacked messd and its man page.
  sed "s#/usr/bin/messd#$root/usr/bin/messd#" "$unit" >"$tmp/messd.service"
  if out=$(MANPATH="$root/usr/share/man" systemd-analyze verify "$tmp/messd.service" 2>&1) && [ -z "$out" ]; then
    echo "messd.service: systemd-analyze verify passes"
  elif grep -qi 'system has not been booted with systemd\|failed to connect\|no such file or directory.*bus' <<<"$out"; then
    echo "systemd-analyze cannot verify here (no systemd): $out"
  else
    fail "systemd-analyze verify:"; echo "$out"
  fi
fi

# Installed, upgraded, removed and purged by dpkg into an empty root: the maintainer scripts run
# (DPKG_ROOT set, so they leave this system alone), an edited configuration survives the
# upgrade and the removal, the purge takes it.
if [ "$(id -u)" -ne 0 ]; then
  echo "not root: the install into an empty root is not tried"
else
  droot=$tmp/dpkg-root
  mkdir -p "$droot/var/lib/dpkg/info" "$droot/var/lib/dpkg/updates" "$droot/var/log"
  touch "$droot/var/lib/dpkg/status"
  dpkg_r() { dpkg --root="$droot" --force-script-chrootless --force-depends --force-confold "$@" >>"$tmp/dpkg.log" 2>&1; }
  if ! dpkg_r -i "$deb"; then fail "dpkg -i into an empty root:"; cat "$tmp/dpkg.log"
  else
    dconf=$droot/etc/imess/messd.json
    sed -i 's/"report_hz": 10/"report_hz": 25/' "$dconf"
    dpkg_r -i "$deb" || fail "dpkg -i again (an upgrade)"
    grep -q '"report_hz": 25' "$dconf" || fail "the upgrade replaced the edited /etc/imess/messd.json"
    dpkg_r -r imess || fail "dpkg -r"
    [ ! -e "$droot/usr/bin/messd" ] && [ -f "$dconf" ] || fail "dpkg -r: messd should be gone and the configuration kept"
    dpkg_r -P imess || fail "dpkg -P"
    [ ! -e "$dconf" ] || fail "dpkg -P kept /etc/imess/messd.json"
    [ $status -eq 0 ] && echo "dpkg into an empty root: installed, upgraded keeping the edited configuration, removed, purged"
  fi
fi

if command -v lintian >/dev/null; then
  # Errors fail; warnings and infos are shown. Overridden nowhere: what it says is what a user sees.
  out=$(lintian --fail-on error --display-info --tag-display-limit 0 "$deb" 2>&1 | grep -v "^running with root privileges"
        exit "${PIPESTATUS[0]}"); rc=$?
  echo "lintian: $(grep -c '^E:' <<<"$out") errors, $(grep -c '^W:' <<<"$out") warnings, $(grep -c '^I:' <<<"$out") infos"
  [ -n "$out" ] && echo "$out"
  [ $rc -eq 0 ] || fail "lintian found errors"
else
  echo "lintian not installed: not run (scripts/package installs and runs it)"
fi

[ $status -eq 0 ] && echo "$(basename "$deb"): every check passed"
exit $status
