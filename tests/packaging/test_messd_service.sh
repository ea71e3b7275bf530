#!/usr/bin/env bash
# packaging/messd.service: systemd-analyze verify accepts it, and it keeps what README.md
# promises (unprivileged user, capabilities, state directory, limits, restart policy).
# Usage: test_messd_service.sh UNIT MESSD. Exit 77 (skipped) without systemd-analyze.
set -uo pipefail
unit=$1 messd=$2
if ! command -v systemd-analyze >/dev/null; then
  echo "systemd-analyze not found: skipped"
  exit 77
fi
status=0
for line in 'DynamicUser=yes' 'User=imess' 'StateDirectory=imess' 'Restart=on-failure' 'LimitMEMLOCK=infinity' \
            'AmbientCapabilities=CAP_SYS_NICE CAP_IPC_LOCK CAP_SYS_RAWIO' 'LimitRTPRIO=' 'LimitNOFILE=' \
            'ExecStart=/usr/local/bin/messd --config /etc/imess/messd.json --journal /var/lib/imess'; do
  grep -q "^$line" "$unit" || { echo "FAIL: $unit lacks '$line'"; status=1; }
done
# The unit names the installed /usr/local/bin/messd, which a build machine does not have:
# verify a copy that runs the messd just built instead.
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
sed "s#/usr/local/bin/messd#$messd#" "$unit" >"$tmp/messd.service"
if ! out=$(systemd-analyze verify "$tmp/messd.service" 2>&1) || [ -n "$out" ]; then
  echo "FAIL: systemd-analyze verify:"
  echo "$out"
  status=1
fi
[ $status -eq 0 ] && echo "messd.service verified"
exit $status
