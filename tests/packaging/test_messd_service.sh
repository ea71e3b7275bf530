#!/usr/bin/env bash
# packaging/messd.service: systemd-analyze verify accepts it, and it keeps what README.md
# promises (unprivileged user, capabilities, state directory, limits, restart policy).
# Usage: test_messd_service.sh UNIT MESSD MAN_PAGE. Exit 77 (skipped) without systemd-analyze.
set -uo pipefail
unit=$1 messd=$2 man_page=$3
if ! command -v systemd-analyze >/dev/null; then
  echo "systemd-analyze not found: skipped"
  exit 77
fi
status=0
for line in 'DynamicUser=yes' 'User=imess' 'StateDirectory=imess' 'Restart=on-failure' 'LimitMEMLOCK=infinity' \
            'AmbientCapabilities=CAP_SYS_NICE CAP_IPC_LOCK CAP_SYS_RAWIO' 'LimitRTPRIO=' 'LimitNOFILE=' \
            'ExecStart=/usr/bin/messd --config /etc/imess/messd.json --journal /var/lib/imess' \
            'SupplementaryGroups=lp dialout'; do
  grep -q "^$line" "$unit" || { echo "FAIL: $unit lacks '$line'"; status=1; }
done
# The unit names the installed /usr/bin/messd, which a build machine does not have:
# verify a copy that runs the messd just built instead (the package's test, test_deb.sh,
# verifies the unit as packed).
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
sed "s#/usr/bin/messd#$messd#" "$unit" >"$tmp/messd.service"
# Its Documentation= is man:messd(8), which verify looks up: the page from packaging/man/.
mkdir -p "$tmp/man/man8" && ln -s "$man_page" "$tmp/man/man8/messd.8"
if ! out=$(MANPATH="$tmp/man" systemd-analyze verify "$tmp/messd.service" 2>&1) || [ -n "$out" ]; then
  echo "FAIL: systemd-analyze verify:"
  echo "$out"
  status=1
fi
[ $status -eq 0 ] && echo "messd.service verified"
exit $status
