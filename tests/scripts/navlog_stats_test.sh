#!/usr/bin/env bash
# scripts/navlog_stats on a hand-made navigation log:
#   t 0.2: the target jumps 5 m (far change 1), t 0.4: back again after one map (far change 2,
#   and change 1's target came back); both changes turn on the spot: 0.4 s + 0.2 s, printed as 1;
#   a look at (0, 0) at t 0.6 and at (0.3, 0) at t 40: two looks, the second repeated (within
#   0.5 m, more than 30 s later). And a directory without logs fails with a message.
set -euo pipefail
repo="$1"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cat > "$work/world_1_seed_1.navlog.csv" <<'CSV'
t,target_x,target_y,phase
0,0,0,driving
0.2,5,0,turning
0.4,0,0,turning
0.6,0,0,looking_at_frontier
0.8,0,0,driving
40,0.3,0,looking_at_frontier
CSV
row="$(python3 "$repo/scripts/navlog_stats" "$work" | grep '^| world_1_seed_1 ')"
expected="| world_1_seed_1 | 2 | 1 | 1 | 0 | 1 | 2 | 1 |"
[ "$row" = "$expected" ] || { echo "got      $row"; echo "expected $expected"; exit 1; }
mkdir "$work/empty"
if python3 "$repo/scripts/navlog_stats" "$work/empty" 2> "$work/err"; then echo "an empty directory passed"; exit 1; fi
grep -q "no \*_seed_\*.navlog.csv" "$work/err" || { cat "$work/err"; exit 1; }
echo "navlog_stats: counts as expected"
