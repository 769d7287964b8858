# What every measurement of tools/ shares, written once: sourced by tools/bench/ab,
# tools/bench/show-speed and the studies' scripts (tools/studies/*/). The caller sets `set -euo
# pipefail` (or `set -uo pipefail`) first.
#
#   root                    the project folder (the scripts run from it)
#   me                      the script's path from there, for messages
#   from_caller PATH        PATH from the folder the script was started in when it is there, else PATH
#                           (the scripts cd to the project, and take paths from either)
#   die MESSAGE             "$me: MESSAGE" on standard error, exit 2
#   at_exit COMMAND         COMMAND (a string) run when the script exits, whatever ends it; the last
#                           registered runs first. Scripts register here rather than with `trap ... EXIT`.
#   scratch VAR NAME        sets VAR to a fresh folder /tmp/NAME.XXXXXX, removed on exit (a variable,
#                           not printed: an exit action registered in a $(...) subshell would be lost)
#   locked COMMAND...       COMMAND (a program or a shell function) run holding `flock -x` on the file
#                           CPU_LOCK names, when it is set: measurements on a shared machine then never
#                           overlap. A shell function runs in this shell, so a time it takes inside
#                           counts none of the wait for the lock. Without CPU_LOCK, COMMAND runs as is.
#   now                     the time in nanoseconds; seconds_since START: the seconds since then (%.3f)
#   jar_of JAR|REVISION     prints the absolute path of a render jar: the file given (from_caller),
#                           or the git revision built once into build/revisions/COMMIT/render.jar
#                           (so that a comparison with an old commit names the commit, not a jar
#                           someone built by hand)
#   find_java VERSION       prints the java of a JDK VERSION: $JAVA<VERSION>, else the first
#                           /usr/lib/jvm/*VERSION*/bin/java, else `java` of the PATH when it is VERSION
#   tool_jars               builds render.jar and render-tools.jar (the Java programs of tools/) when
#                           out of date; prints their class path
#   STATS_AWK               awk functions, for `awk "$STATS_AWK"'...'`: sort_numbers(x, n) sorts x[1..n];
#                           quantile(x, n, q) of sorted x, linear between ranks (the median of an even
#                           count is the mean of the middle two)
#   summarize FIGURE...     the table of a measurement from rows on standard input, tab-separated:
#                           GROUP ROUND SIDE VALUE... (one VALUE per FIGURE, - where there is none).
#                           Per group, figure and side: the median over the rounds, the quartiles and
#                           the range; for every side after the first (the first seen is the baseline):
#                           the median, quartiles and range of the per-round ratios side / baseline.
#                           Ratios of one round cancel the machine's drift between rounds, which is
#                           why the tools interleave the sides within a round.

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
# the script's name in messages: its path in the project (tools/studies/skip-study/run, not run)
me=$(realpath --relative-to="$root" "$0")
caller=$PWD
from_caller() { if [[ $1 != /* && -e $caller/$1 ]]; then echo "$caller/$1"; else echo "$1"; fi; }

die() {
  echo "$me: $*" >&2
  exit 2
}

_exit_actions=()
_run_exit_actions() {
  local i
  for ((i = ${#_exit_actions[@]} - 1; i >= 0; i--)); do
    eval "${_exit_actions[i]}" || true
  done
}
at_exit() {
  _exit_actions+=("$1")
}
trap _run_exit_actions EXIT
# an interrupted or terminated script still runs its exit actions
trap 'exit 130' INT
trap 'exit 143' TERM

scratch() {
  local dir
  dir=$(mktemp -d "/tmp/$2.XXXXXX")
  at_exit "rm -rf '$dir'"
  printf -v "$1" '%s' "$dir"
}

locked() {
  if [ -z "${CPU_LOCK:-}" ]; then
    "$@"
    return
  fi
  local fd status=0
  exec {fd}>>"$CPU_LOCK"
  flock -x "$fd"
  "$@" || status=$?
  # unlocked explicitly: a process started inside may still hold the descriptor open
  flock -u "$fd"
  exec {fd}>&-
  return $status
}

now() { date +%s%N; }
seconds_since() { awk -v a="$1" -v b="$(now)" 'BEGIN { printf "%.3f", (b - a) / 1e9 }'; }

jar_of() {
  local what commit dir
  what=$(from_caller "$1")
  if [ -f "$what" ]; then
    realpath "$what"
    return
  fi
  commit=$(git -C "$root" rev-parse --verify -q "$what^{commit}") || die "$what is neither a jar nor a git revision"
  dir=$root/build/revisions/$commit
  if [ ! -f "$dir/render.jar" ]; then
    echo "$me: building $what ($commit) into $dir/render.jar (once)" >&2
    # in a subshell of its own, with its own exit action: jar_of runs inside $(...), where at_exit's
    # would be lost. The revision's files as committed, outside the working tree: git's state is untouched.
    (
      src=$(mktemp -d /tmp/revision.XXXXXX)
      trap 'rm -rf "$src"' EXIT
      git -C "$root" archive "$commit" | tar -x -C "$src"
      if ! (cd "$src" && gradle -q --console=plain jar) > "$src/build.log" 2>&1; then
        cat "$src/build.log" >&2
        exit 1
      fi
      mkdir -p "$dir"
      cp "$src/build/libs/render.jar" "$dir/render.jar.partial" && mv "$dir/render.jar.partial" "$dir/render.jar"
    ) || die "building $what ($commit) failed"
  fi
  echo "$dir/render.jar"
}

find_java() {
  local version=$1 named dir
  named=JAVA$1
  if [ -n "${!named:-}" ]; then
    echo "${!named}"
    return
  fi
  for dir in /usr/lib/jvm/*"$version"*; do
    if [ -x "$dir/bin/java" ]; then
      echo "$dir/bin/java"
      return
    fi
  done
  if java -version 2>&1 | grep -q "version \"$version[.\"]"; then
    echo java
    return
  fi
  die "no JDK $version found: set $named=.../bin/java"
}

tool_jars() {
  local log
  log=$(cd "$root" && gradle -q --console=plain jar toolsJar 2>&1) || { echo "$log" >&2; die "gradle jar toolsJar failed"; }
  echo "$root/build/libs/render-tools.jar:$root/build/libs/render.jar"
}

STATS_AWK='
function sort_numbers(x, n,   i, j, t) {
  for (i = 2; i <= n; i++) { t = x[i]; for (j = i - 1; j >= 1 && x[j] > t; j--) x[j + 1] = x[j]; x[j + 1] = t }
}
function quantile(x, n, q,   h, lo) {
  if (n == 0) return "-"
  h = (n - 1) * q + 1; lo = int(h)
  return lo >= n ? x[n] : x[lo] + (h - lo) * (x[lo + 1] - x[lo])
}
'

summarize() {
  awk -F'\t' -v names="$*" "$STATS_AWK"'
    function put(key, v) { if (v != "-" && v != "") { count[key]++; value[key, count[key]] = v + 0 } }
    # "median [q1-q3] (min-max)" of the values under key, or - when none
    function stats(key,   n, i, x) {
      n = count[key] + 0
      if (n == 0) return sprintf("%-34s", "-")
      for (i = 1; i <= n; i++) x[i] = value[key, i]
      sort_numbers(x, n)
      return sprintf("%-9s %-24s", fmt(quantile(x, n, 0.5)),
                     "[" fmt(quantile(x, n, 0.25)) "-" fmt(quantile(x, n, 0.75)) "] (" fmt(x[1]) "-" fmt(x[n]) ")")
    }
    function fmt(v) { return v == int(v) && v >= 10 ? sprintf("%d", v) : v >= 100 ? sprintf("%.1f", v) : v >= 10 ? sprintf("%.2f", v) : sprintf("%.3f", v) }
    BEGIN { nf = split(names, figure, " ") }
    {
      g = $1; r = $2; s = $3
      if (!(g in seen)) { seen[g] = 1; groups[++ng] = g }
      if (!((g, s) in sideseen)) { sideseen[g, s] = 1; sides[g, ++ns[g]] = s }
      if (!((g, r) in roundseen)) { roundseen[g, r] = 1; roundlist[g, ++rounds[g]] = r }
      for (f = 1; f <= nf; f++) { put(g SUBSEP f SUBSEP s, $(f + 3)); v[g, f, s, r] = $(f + 3) }
    }
    END {
      for (k = 1; k <= ng; k++) {
        g = groups[k]; base = sides[g, 1]
        printf "%s, %d round%s: median [quartiles] (range) of each side; ratio to %s: of the per-round ratios\n", g, rounds[g], rounds[g] == 1 ? "" : "s", base
        printf "  %-22s %-10s %-34s %s\n", "figure", "side", "median [q1-q3] (min-max)", "ratio to " base
        for (f = 1; f <= nf; f++) {
          for (i = 1; i <= ns[g]; i++) {
            s = sides[g, i]; line = sprintf("  %-22s %-10s %s", figure[f], s, stats(g SUBSEP f SUBSEP s))
            if (i > 1) {
              for (j = 1; j <= rounds[g]; j++) {
                r = roundlist[g, j]; a = v[g, f, base, r]; b = v[g, f, s, r]
                if (a != "-" && a != "" && b != "-" && b != "" && a + 0 != 0) put("ratio" SUBSEP g SUBSEP f SUBSEP s, b / a)
              }
              line = line " " stats("ratio" SUBSEP g SUBSEP f SUBSEP s)
            }
            sub(/ +$/, "", line); print line
          }
        }
      }
    }'
}
