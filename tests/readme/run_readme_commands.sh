#!/usr/bin/env bash
# Runs the shell commands of README.md's ```sh blocks as a user would type them, from the
# repository's root, and fails naming the first one that exits non-zero. A command is one line,
# or several joined by a trailing backslash. Skipped, and why:
#   scripts/demo, scripts/test  the set-up this test runs inside (CI runs scripts/test first);
#   "# long"                    minutes of work (the office exploration);
#   "# GUI"                     needs a display (navlog-viewer, SceneViewer3D).
# `build/` in a command is replaced by the build tree under test when that is elsewhere.
# usage: run_readme_commands.sh SOURCE_DIR BUILD_DIR
set -uo pipefail
source_dir="$1"
build_dir="$(cd "$2" && pwd)"
cd "$source_dir"
mkdir -p out

commands=()
in_block=0
pending=""
while IFS= read -r line; do
  if [[ $in_block -eq 0 ]]; then
    [[ "$line" == '```sh' ]] && in_block=1
    continue
  fi
  if [[ "$line" == '```' ]]; then
    in_block=0
    continue
  fi
  if [[ "$line" == *'\' ]]; then
    pending+="${line%\\} "
    continue
  fi
  line="$pending$line"
  pending=""
  [[ "$line" =~ ^[[:space:]]*$ ]] && continue
  commands+=("$line")
done < README.md

ran=0
for command in "${commands[@]}"; do
  if [[ "$command" =~ ^scripts/(demo|test)([[:space:]]|$) || "$command" == *"# long"* || "$command" == *"# GUI"* ]]; then
    echo "skipped: $command"
    continue
  fi
  to_run="$command"
  if [[ "$build_dir" != "$source_dir/build" ]]; then to_run="${to_run//build\//$build_dir/}"; fi
  echo "running: $command"
  if ! timeout 120 bash -c "$to_run" > /dev/null; then
    echo "README.md command failed: $command" >&2
    exit 1
  fi
  ran=$((ran + 1))
done
if [[ $ran -eq 0 ]]; then
  echo "README.md: no command found to run" >&2
  exit 1
fi
echo "ran $ran README.md commands"
