#!/usr/bin/env bash
# The man pages in packaging/man/ name exactly the options each program's --help names: every
# option of --help (and of the commands whose own --help it points to, as `messcap inspect
# --help`) appears in the page's OPTIONS sections, and the page documents no option --help
# lacks. Also: each page renders without a groff warning.
# Usage: test_man_options.sh MAN_DIR BIN_DIR PROGRAM...
# messcard's page is checked only where messcard is built (it may not be, yet).
set -uo pipefail
man_dir=$1 bin_dir=$2
shift 2
programs=("$@")

# Options in help text: the usage lines (from "usage:" to the first line not indented) and the
# terms of the option lines (an indented line starting with '-', up to two spaces).
help_options() {
  awk '
    /^usage:/ { in_usage = 1; print; next }
    in_usage && /^[ \t]/ { print; next }
    { in_usage = 0 }
    /^[ \t]+-/ { sub(/^[ \t]+/, ""); sub(/  .*/, ""); print }
  ' | grep -oE '(^|[][ |,])--?[A-Za-z][A-Za-z0-9-]*([][ |,=]|$)' \
    | sed -E 's/^[][ |,]*//; s/[][ |,=]*$//' | sort -u
}

# Options of a man page: the tagged paragraphs (.TP) of every section named "... OPTIONS".
man_options() {
  awk '
    /^\.SH/ { in_options = ($0 ~ /OPTIONS/); next }
    in_options && /^\.TP/ { getline; print }
  ' "$1" | sed -E 's/^\.[A-Z]+ ?//; s/\\f[BIRP]//g; s/\\-/-/g; s/"/ /g' \
    | grep -oE '(^|[][ |,])--?[A-Za-z][A-Za-z0-9-]*([][ |,=]|$)' \
    | sed -E 's/^[][ |,]*//; s/[][ |,=]*$//' | sort -u
}

status=0
checked=0
for p in "${programs[@]}"; do
  page=$(ls "$man_dir/$p".[18] 2>/dev/null | head -1)
  if [ -z "$page" ]; then echo "FAIL: $p has no man page in $man_dir"; status=1; continue; fi
  if [ ! -x "$bin_dir/$p" ]; then echo "FAIL: $bin_dir/$p is not built"; status=1; continue; fi
  help=$("$bin_dir/$p" --help 2>&1) || { echo "FAIL: $p --help exits $?"; status=1; continue; }
  # Commands with a help of their own: "(messcap inspect --help)".
  for cmd in $(grep -oE "\($p [a-z]+ --help\)" <<<"$help" | awk '{print $2}' | sort -u); do
    help+=$'\n'$("$bin_dir/$p" "$cmd" --help 2>&1)
  done
  from_help=$(help_options <<<"$help")
  from_man=$(man_options "$page")
  missing=$(comm -23 <(echo "$from_help") <(echo "$from_man"))
  extra=$(comm -13 <(echo "$from_help") <(echo "$from_man"))
  if [ -z "$from_help" ]; then echo "FAIL: no option found in $p --help"; status=1; fi
  if [ -n "$missing" ]; then echo "FAIL: $(basename "$page") lacks options of $p --help:" $missing; status=1; fi
  if [ -n "$extra" ]; then echo "FAIL: $(basename "$page") documents options $p --help does not name:" $extra; status=1; fi
  if command -v groff >/dev/null; then
    warnings=$(LC_ALL=C.UTF-8 groff -man -ww -z -Tutf8 "$page" 2>&1)
    [ -n "$warnings" ] && { echo "FAIL: groff warns about $(basename "$page"):"; echo "$warnings"; status=1; }
  fi
  [ -z "$missing$extra" ] && echo "$p: $(wc -w <<<"$from_help") options, $(basename "$page") agrees"
  checked=$((checked + 1))
done
for page in "$man_dir"/*.[18]; do
  name=$(basename "${page%.*}")
  case " ${programs[*]} " in
    *" $name "*) ;;
    *) echo "$(basename "$page"): $name is not built here, its options are not checked" ;;
  esac
done
[ $checked -eq 0 ] && { echo "FAIL: no program checked"; status=1; }
exit $status
