#!/usr/bin/env bash
# run_key_table.sh KEY_TABLE README: the README's key table is the one common/platform/keys.c holds.
set -u
table=$1 readme=$2
want=$("$table") || { echo "FAIL: key_table exited $?"; exit 1; }
have=$(sed -n '/^<!-- keys -->$/,/^<!-- \/keys -->$/p' "$readme" | sed '1d;$d')
if [ "$have" = "$want" ]; then
  echo "ok   the README's key table is common/platform/keys.c's ($(grep -c '^| `' <<<"$want") keys)"
else
  echo "FAIL: the README's key table differs from common/platform/keys.c; paste the output of key_table:"
  diff <(echo "$have") <(echo "$want")
  exit 1
fi
