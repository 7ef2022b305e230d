#!/usr/bin/env bash
# Builds and installs the Player robot server (3.1.1-dev, git cb1e0b1) and the Stage simulator
# (4.3.0, git 281ed73) with its Player plugin, from their pinned sources, into a prefix.
#
#   player-stage.sh install [--prefix DIR] [--source DIR|github] [--jobs N] [--no-deps]
#   player-stage.sh env [--prefix DIR]        print the prefix's env.sh path (exit 1 if not installed)
#   player-stage.sh tier [--python PY] [maven args...]
#                  the real-Player test tier (tests/org.stagecraft.player.it and the real-Player demo test of
#                  tests/org.stagecraft.demo.it), run by ./stagecraft test:
#                  builds (or reuses) Player/Stage from ../shared/third-party into the checkout's
#                  .player-stage/ (or uses $STAGECRAFT_PLAYER_STAGE if it holds an install), runs the tier
#                  with Maven and prints its test count; says plainly when it cannot run, and why
#
# --source DIR   a folder holding the two pristine tarballs (player-*.tar.gz, stage-*.tar.gz; their
#                SHA256SUMS file is checked when there is one) or the two unpacked source folders
#                (player-*/ and stage-*/ or Stage-*/)
# --source github (the default) downloads the pinned commits from GitHub (codeload tarballs)
# --prefix DIR   where to install; default $STAGECRAFT_PLAYER_STAGE, else
#                ${XDG_DATA_HOME:-$HOME/.local/share}/stagecraft/player-stage
#
# Only three build changes are made to Player, none to its logic (see docs/player-stage.md):
#   1. -DCMAKE_CXX_FLAGS=-std=gnu++14            (C++17 rejects `bool++` in libplayercore/message.cc)
#   2. -DBoost_NO_BOOST_CMAKE=ON -DUSE_BOOST_SIGNALS=OFF   (Boost 1.74: FindBoost, no `signals`)
#   3. libplayerc's SWIG file: PyBuffer_FromMemory((void*)$1, ...) -> PyBytes_FromStringAndSize((const char*)$1, ...)
#      (Python 3 has no PyBuffer_FromMemory; only the Python bindings need it)
# Re-running with the same sources and the same patch version reuses the installed build (a stamp
# in the prefix holds the sources' checksums). The prefix gets env.sh: PATH, LD_LIBRARY_PATH,
# PLAYERPATH, STAGEPATH and PYTHONPATH (libplayerc's Python bindings).
set -euo pipefail

PLAYER_COMMIT=cb1e0b1349735bcad64eba8846b422f2dc59b768
STAGE_COMMIT=281ed731ed56b23d0879a2c765d4a20824a6d58a
PLAYER_URL="https://codeload.github.com/playerproject/player/tar.gz/$PLAYER_COMMIT"
STAGE_URL="https://codeload.github.com/rtv/Stage/tar.gz/$STAGE_COMMIT"
# Bump when the build changes, the configure options or what is installed change: old stamps are then stale.
PATCH_VERSION=1
# fluid: libfltk1.3-dev only recommends it, but its CMake config (FLTK-Targets.cmake) fails without /usr/bin/fluid
DEBIAN_BUILD_DEPS=(build-essential cmake pkg-config swig python3-dev libboost-dev libboost-thread-dev
  libboost-system-dev libfltk1.3-dev libgl-dev libglu1-mesa-dev libltdl-dev libjpeg-dev libpng-dev zlib1g-dev
  libtirpc-dev fluid)

say() { echo "player-stage: $*" >&2; }
die() { echo "player-stage: ERROR: $*" >&2; exit 1; }

default_prefix() {
  if [ -n "${STAGECRAFT_PLAYER_STAGE:-}" ]; then echo "$STAGECRAFT_PLAYER_STAGE"; return; fi
  echo "${XDG_DATA_HOME:-$HOME/.local/share}/stagecraft/player-stage"
}

abs_path() { # an absolute path for $1 (which need not exist yet)
  case "$1" in /*) echo "$1" ;; *) echo "$PWD/$1" ;; esac
}

# ---------------------------------------------------------------------------------------------- deps
install_deps() {
  if ! command -v dpkg-query >/dev/null; then
    say "not a Debian system (no dpkg-query): make sure these are installed (Debian names): ${DEBIAN_BUILD_DEPS[*]}"
    return 0
  fi
  local missing=() p
  for p in "${DEBIAN_BUILD_DEPS[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "ok installed" || missing+=("$p")
  done
  if [ "${#missing[@]}" = 0 ]; then
    say "build dependencies: all installed"
    return 0
  fi
  local cmd=(apt-get install -y --no-install-recommends "${missing[@]}")
  if [ "$(id -u)" = 0 ]; then
    say "installing the missing build dependencies with apt-get: ${missing[*]}"
  elif command -v sudo >/dev/null && sudo -n true 2>/dev/null; then
    say "installing the missing build dependencies with sudo apt-get: ${missing[*]}"
    cmd=(sudo "${cmd[@]}")
  else
    die "missing build dependencies: ${missing[*]}
  install them (as root) and run this again:
    sudo apt-get install -y --no-install-recommends ${missing[*]}"
  fi
  local log="$LOG_DIR/apt-get.log"
  if ! DEBIAN_FRONTEND=noninteractive "${cmd[@]}" >"$log" 2>&1; then
    say "apt-get install failed, trying once more after apt-get update"
    local upd=(apt-get update); [ "${cmd[0]}" = sudo ] && upd=(sudo apt-get update)
    { "${upd[@]}" && DEBIAN_FRONTEND=noninteractive "${cmd[@]}"; } >>"$log" 2>&1 \
      || fail_step "installing the build dependencies (${cmd[*]})" "$log"
  fi
}

# ------------------------------------------------------------------------------------------- helpers
fail_step() { # $1 what failed, $2 its log
  echo "player-stage: ERROR: $1 failed. Last lines of its log:" >&2
  tail -n 30 "$2" | sed 's/^/    | /' >&2
  echo "player-stage: full log: $2" >&2
  exit 1
}

step() { # $1 label, $2 log file, rest: the command
  local label="$1" log="$2"; shift 2
  local t0=$SECONDS
  say "$label ... (log: $log)"
  if ! "$@" >"$log" 2>&1; then fail_step "$label" "$log"; fi
  say "$label done in $((SECONDS - t0)) s"
}

sha256_of_dir() { # a checksum over every file's path and content in a folder
  (cd "$1" && find . -type f ! -path './.git/*' -print0 | LC_ALL=C sort -z | xargs -0 sha256sum) | sha256sum | cut -d' ' -f1
}

# Finds the sources in $SOURCE; sets PLAYER_SRC_KIND/PLAYER_SRC (tarball|dir) and the same for STAGE.
locate_sources() {
  local src="$1" f
  PLAYER_SRC=""; STAGE_SRC=""
  if [ "$src" = github ]; then
    command -v curl >/dev/null || command -v wget >/dev/null || die "--source github needs curl or wget"
    # kept in the prefix: a re-run checks the same bytes, so the stamp matches and nothing is rebuilt
    local dl="$PREFIX_DIR/downloads"; mkdir -p "$dl"
    download "$PLAYER_URL" "$dl/player-$PLAYER_COMMIT.tar.gz" "player-$PLAYER_COMMIT/"
    download "$STAGE_URL" "$dl/Stage-$STAGE_COMMIT.tar.gz" "Stage-$STAGE_COMMIT/"
    PLAYER_SRC="$dl/player-$PLAYER_COMMIT.tar.gz"; PLAYER_SRC_KIND=tarball
    STAGE_SRC="$dl/Stage-$STAGE_COMMIT.tar.gz"; STAGE_SRC_KIND=tarball
    return
  fi
  [ -d "$src" ] || die "--source $src is not a folder (give the folder holding the Player and Stage tarballs or source folders, or 'github')"
  src="$(cd "$src" && pwd)"
  shopt -s nullglob nocaseglob
  local found
  found=("$src"/player-*.tar.gz "$src"/player-*.tgz)
  [ "${#found[@]}" -le 1 ] || die "more than one Player tarball in $src (${found[*]##*/}): keep one"
  [ "${#found[@]}" = 0 ] || { PLAYER_SRC="${found[0]}"; PLAYER_SRC_KIND=tarball; }
  found=("$src"/stage-*.tar.gz "$src"/stage-*.tgz)
  [ "${#found[@]}" -le 1 ] || die "more than one Stage tarball in $src (${found[*]##*/}): keep one"
  [ "${#found[@]}" = 0 ] || { STAGE_SRC="${found[0]}"; STAGE_SRC_KIND=tarball; }
  if [ -z "$PLAYER_SRC" ]; then
    for f in "$src"/player*/ "$src"; do
      [ -f "$f/libplayercore/message.cc" ] && { PLAYER_SRC="${f%/}"; PLAYER_SRC_KIND=dir; break; }
    done
  fi
  if [ -z "$STAGE_SRC" ]; then
    for f in "$src"/stage*/ "$src"; do
      [ -f "$f/libstage/stage.hh" ] && { STAGE_SRC="${f%/}"; STAGE_SRC_KIND=dir; break; }
    done
  fi
  shopt -u nullglob nocaseglob
  [ -n "$PLAYER_SRC" ] || die "no Player source in $src (expected player-*.tar.gz or a player-*/ folder with libplayercore/)"
  [ -n "$STAGE_SRC" ] || die "no Stage source in $src (expected stage-*.tar.gz or a stage-*/ folder with libstage/)"
  if [ -f "$src/SHA256SUMS" ]; then
    local t name
    for t in "$PLAYER_SRC" "$STAGE_SRC"; do
      [ -f "$t" ] || continue
      name="$(basename "$t")"
      if grep -q "  \*\?$name\$" "$src/SHA256SUMS"; then
        (cd "$src" && grep "  \*\?$name\$" SHA256SUMS | sha256sum -c --quiet >/dev/null 2>&1) \
          || die "$t does not match its checksum in $src/SHA256SUMS (a damaged or different file)"
        say "checksum OK: $name (SHA256SUMS)"
      else
        say "note: $name is not listed in $src/SHA256SUMS, not checked"
      fi
    done
  fi
}

download() { # $1 url, $2 file, $3 the top folder the archive must have (names the pinned commit)
  [ -s "$2" ] && return 0
  say "downloading $1"
  if command -v curl >/dev/null; then
    curl -fsSL --retry 3 -o "$2.part" "$1" || die "cannot download $1 (no internet? give --source DIR with the tarballs)"
  else
    wget -q -O "$2.part" "$1" || die "cannot download $1 (no internet? give --source DIR with the tarballs)"
  fi
  local top
  top="$(tar -tzf "$2.part" 2>/dev/null | head -1 || true)"
  [ "$top" = "$3" ] || die "$1 is not the expected archive (its top folder is '$top', expected '$3'); kept as $2.part"
  mv "$2.part" "$2"
}

source_sum() { # $1 kind, $2 path
  if [ "$1" = tarball ]; then sha256sum "$2" | cut -d' ' -f1; else sha256_of_dir "$2"; fi
}

unpack() { # $1 kind, $2 path, $3 destination folder (becomes the source tree)
  rm -rf "$3"; mkdir -p "$3"
  if [ "$1" = tarball ]; then
    tar -xzf "$2" -C "$3" --strip-components=1 || die "cannot unpack $2"
  else
    cp -a "$2/." "$3/" || die "cannot copy $2"
  fi
}

# Build change 3: the one SWIG line for Python 3. Fails unless exactly that line is found.
patch_swig_pybuffer() {
  local i="$1/client_libs/libplayerc/bindings/python/playerc.i"
  [ -f "$i" ] || die "$i not found: is this Player 3.1?"
  local n
  n=$(grep -c 'PyBuffer_FromMemory((void\*)\$1,' "$i" || true)
  [ "$n" = 1 ] || die "$i: expected exactly one 'PyBuffer_FromMemory((void*)\$1,' line, found $n (not the pinned Player source?)"
  sed -i 's/PyBuffer_FromMemory((void\*)\$1,/PyBytes_FromStringAndSize((const char*)$1,/' "$i"
  grep -q 'PyBytes_FromStringAndSize((const char\*)\$1,' "$i" || die "$i: the SWIG change did not apply"
}

# ------------------------------------------------------------------------------------------- install
# Player: unpack, build change 3, configure with build changes 1 and 2, compile, install (uses the
# variables of cmd_install: prefix, py, jobs, WORK, LOG_DIR, PLAYER_SRC*).
build_player() {
  local psrc="$WORK/player-src" pbld="$WORK/player-build"
  say "unpacking Player"
  unpack "$PLAYER_SRC_KIND" "$PLAYER_SRC" "$psrc"
  [ -f "$psrc/libplayercore/message.cc" ] || die "$PLAYER_SRC does not hold Player's source (no libplayercore/message.cc)"
  patch_swig_pybuffer "$psrc"
  say "applied build change 3 (SWIG PyBuffer line for Python 3)"
  rm -rf "$pbld"; mkdir -p "$pbld"
  step "configuring Player (C++14, Boost through FindBoost)" "$LOG_DIR/player-configure.log" \
    cmake -S "$psrc" -B "$pbld" -DCMAKE_INSTALL_PREFIX="$prefix" -DCMAKE_BUILD_TYPE=Release \
      -DCMAKE_CXX_FLAGS=-std=gnu++14 -DBoost_NO_BOOST_CMAKE=ON -DUSE_BOOST_SIGNALS=OFF \
      -DPYTHON_EXECUTABLE="$py" -DBUILD_PYTHONC_BINDINGS=ON
  step "compiling Player (make -j$jobs; 80-112 s on 2 idle cores, 4-7 min on a busy machine)" "$LOG_DIR/player-make.log" make -C "$pbld" -j"$jobs"
  step "installing Player" "$LOG_DIR/player-install.log" make -C "$pbld" install
  [ -x "$prefix/bin/player" ] || die "Player's install did not produce $prefix/bin/player (see $LOG_DIR/player-install.log)"
  # Player installs its examples as source only; keep the built C++ example clients too.
  local ex="$prefix/share/player/examples/bin" e
  mkdir -p "$ex"
  for e in laserobstacleavoid randomwalk; do
    [ -x "$pbld/examples/libplayerc++/$e" ] && cp "$pbld/examples/libplayerc++/$e" "$ex/"
  done
}

cmd_install() {
  local prefix="" source="github" jobs="" deps=yes
  while [ $# -gt 0 ]; do
    case "$1" in
      --prefix) [ $# -ge 2 ] || die "--prefix needs a folder"; prefix="$2"; shift 2 ;;
      --source) [ $# -ge 2 ] || die "--source needs a folder (or 'github')"; source="$2"; shift 2 ;;
      --jobs) [ $# -ge 2 ] || die "--jobs needs a number"; jobs="$2"; shift 2 ;;
      --no-deps) deps=no; shift ;;
      -h|--help) usage; exit 0 ;;
      *) die "unknown option $1 (install [--prefix DIR] [--source DIR|github] [--jobs N] [--no-deps])" ;;
    esac
  done
  prefix="$(abs_path "${prefix:-$(default_prefix)}")"
  [ "$source" = github ] || [ -d "$source" ] \
    || die "--source $source is not a folder (give the folder holding the Player and Stage tarballs or source folders, or 'github')"
  jobs="${jobs:-$(nproc 2>/dev/null || echo 2)}"
  local t_start=$SECONDS
  mkdir -p "$prefix" || die "cannot create the prefix $prefix"
  PREFIX_DIR="$prefix"; WORK="$prefix/.build"; LOG_DIR="$prefix/logs"
  mkdir -p "$WORK" "$LOG_DIR"
  say "prefix: $prefix"

  locate_sources "$source"
  say "Player source: $PLAYER_SRC"
  say "Stage source:  $STAGE_SRC"
  local psum ssum stamp="$prefix/.stagecraft-player-stage.stamp" want
  psum="$(source_sum "$PLAYER_SRC_KIND" "$PLAYER_SRC")"
  ssum="$(source_sum "$STAGE_SRC_KIND" "$STAGE_SRC")"
  want="player-sha256=$psum
stage-sha256=$ssum
patch-version=$PATCH_VERSION
prefix=$prefix"
  local py=python3
  [ -x /usr/bin/python3 ] && py=/usr/bin/python3
  if [ -f "$stamp" ] && [ "$(cat "$stamp")" = "$want" ] && [ -x "$prefix/bin/player" ] && [ -f "$prefix/env.sh" ]; then
    say "already built from these sources (stamp $stamp): reusing $prefix"
    rm -rf "$WORK"
    write_env "$prefix"
    echo "$prefix/env.sh"
    return 0
  fi
  rm -f "$stamp"

  [ "$deps" = yes ] && install_deps

  # --- Player (its own stamp: a failed Stage build does not cost a second Player build)
  local pstamp="$prefix/.stagecraft-player.stamp" pwant
  pwant="player-sha256=$psum
patch-version=$PATCH_VERSION
prefix=$prefix"
  if [ -f "$pstamp" ] && [ "$(cat "$pstamp")" = "$pwant" ] && [ -x "$prefix/bin/player" ]; then
    say "Player already built from this source (stamp $pstamp): reusing it"
  else
    rm -f "$pstamp"
    build_player
    echo "$pwant" >"$pstamp"
  fi

  # --- Stage (against the Player just installed)
  local ssrc="$WORK/stage-src" sbld="$WORK/stage-build" pc
  say "unpacking Stage"
  unpack "$STAGE_SRC_KIND" "$STAGE_SRC" "$ssrc"
  [ -f "$ssrc/libstage/stage.hh" ] || die "$STAGE_SRC does not hold Stage's source (no libstage/stage.hh)"
  pc="$(find "$prefix"/lib* -name playercore.pc -printf '%h\n' -quit 2>/dev/null)"
  [ -n "$pc" ] || die "no playercore.pc under $prefix after installing Player"
  rm -rf "$sbld"; mkdir -p "$sbld"
  step "configuring Stage" "$LOG_DIR/stage-configure.log" \
    env PKG_CONFIG_PATH="$pc${PKG_CONFIG_PATH:+:$PKG_CONFIG_PATH}" \
    cmake -S "$ssrc" -B "$sbld" -DCMAKE_INSTALL_PREFIX="$prefix" -DCMAKE_BUILD_TYPE=Release
  grep -q "Player version" "$LOG_DIR/stage-configure.log" \
    || fail_step "finding the installed Player for Stage's Player plugin (pkg-config path $pc)" "$LOG_DIR/stage-configure.log"
  step "compiling Stage (make -j$jobs)" "$LOG_DIR/stage-make.log" \
    env PKG_CONFIG_PATH="$pc" make -C "$sbld" -j"$jobs"
  step "installing Stage" "$LOG_DIR/stage-install.log" make -C "$sbld" install

  write_env "$prefix"
  # check what a user will run
  local plugin
  plugin="$(find "$prefix"/lib* -name 'stageplugin.so*' -print -quit 2>/dev/null)"
  [ -n "$plugin" ] || die "Stage's Player plugin (stageplugin.so) is not under $prefix (see $LOG_DIR/stage-make.log)"
  ( . "$prefix/env.sh" && command -v player >/dev/null ) || die "env.sh does not put player on the PATH"
  if ( . "$prefix/env.sh" && "$py" -c "import playerc" ) >"$LOG_DIR/python-check.log" 2>&1; then
    say "libplayerc's Python bindings import (PYTHONPATH in env.sh)"
  else
    say "note: libplayerc's Python bindings do not import (see $LOG_DIR/python-check.log)"
  fi
  echo "$want" >"$stamp"
  rm -rf "$WORK"
  say "installed Player and Stage into $prefix in $((SECONDS - t_start)) s"
  say "use it: . $prefix/env.sh && player -p 6665 pioneer-laser-sonar.cfg"
  echo "$prefix/env.sh"
}

write_env() {
  local prefix="$1" libdir="$1/lib" stagelib pydir
  stagelib="$(find "$prefix/lib" -maxdepth 1 -type d -name 'Stage-*' -print -quit)"
  pydir="$(find "$prefix/lib" -maxdepth 3 -name playerc.py -printf '%h\n' -quit)"
  {
    echo "# Player $PLAYER_COMMIT + Stage $STAGE_COMMIT, built by Stagecraft (releng/tools/player-stage.sh)"
    echo "# use: . $prefix/env.sh"
    echo "STAGECRAFT_PLAYER_STAGE_PREFIX='$prefix'"
    echo "export PATH='$prefix/bin':\"\$PATH\""
    echo "export LD_LIBRARY_PATH='$libdir'\"\${LD_LIBRARY_PATH:+:\$LD_LIBRARY_PATH}\""
    echo "export PLAYERPATH='$libdir'\"\${PLAYERPATH:+:\$PLAYERPATH}\""
    echo "export STAGEPATH='$prefix/share/stage${stagelib:+:$stagelib}'\"\${STAGEPATH:+:\$STAGEPATH}\""
    echo "export PKG_CONFIG_PATH='$libdir/pkgconfig'\"\${PKG_CONFIG_PATH:+:\$PKG_CONFIG_PATH}\""
    if [ -n "$pydir" ]; then
      echo "export PYTHONPATH='$pydir'\"\${PYTHONPATH:+:\$PYTHONPATH}\""
      echo "# the Python libplayerc's bindings (import playerc) were built for"
      echo "export STAGECRAFT_PLAYERC_PYTHON='${py:-python3}'"
    fi
  } >"$prefix/env.sh"
}

cmd_env() {
  local prefix=""
  while [ $# -gt 0 ]; do
    case "$1" in
      --prefix) [ $# -ge 2 ] || die "--prefix needs a folder"; prefix="$2"; shift 2 ;;
      *) die "unknown option $1 (env [--prefix DIR])" ;;
    esac
  done
  prefix="$(abs_path "${prefix:-$(default_prefix)}")"
  [ -f "$prefix/env.sh" ] || die "Player/Stage is not installed in $prefix (run: ./stagecraft player-stage install)"
  echo "$prefix/env.sh"
}

# ---------------------------------------------------------------------------------------------- tier
cmd_tier() {
  local root python="" sources prefix reason=""
  root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
  while [ $# -gt 0 ]; do
    case "$1" in
      --python) [ $# -ge 2 ] || die "--python needs an interpreter"; python="$2"; shift 2 ;;
      *) break ;;
    esac
  done
  sources="$(cd "$root/.." && pwd)/shared/third-party"
  if [ -n "${STAGECRAFT_PLAYER_STAGE:-}" ] && [ -f "$STAGECRAFT_PLAYER_STAGE/env.sh" ]; then
    prefix="$STAGECRAFT_PLAYER_STAGE"
    say "real Player/Stage tier: using the install in \$STAGECRAFT_PLAYER_STAGE=$prefix"
  elif ! ls "$sources"/player-*.tar.gz >/dev/null 2>&1 || ! ls "$sources"/stage-*.tar.gz >/dev/null 2>&1; then
    reason="the pinned Player and Stage sources are not in $sources (player-*.tar.gz, stage-*.tar.gz) and \$STAGECRAFT_PLAYER_STAGE names no install"
  else
    prefix="$root/.player-stage"
    say "real Player/Stage tier: building or reusing Player/Stage from $sources in $prefix"
    if ! "${BASH_SOURCE[0]}" install --prefix "$prefix" --source "$sources" >/dev/null; then
      die "real Player/Stage tier: building Player/Stage failed (see above); the tier did not run"
    fi
  fi
  if [ -n "$reason" ]; then
    echo "stagecraft: real Player/Stage tier NOT run: $reason" >&2
    return 0
  fi
  # the tier: tests/org.stagecraft.player.it, and the demo with the real Player (tests/org.stagecraft.demo.it,
  # whose profile real-player runs only RealPlayerDemoTest; ./stagecraft demo builds the product if it is missing)
  local reports="$root/tests/org.stagecraft.player.it/target/surefire-reports" t0=$SECONDS
  local demo_reports="$root/tests/org.stagecraft.demo.it/target/surefire-reports"
  rm -rf "$reports" "$demo_reports"
  local args=(-B -ntp verify -pl tests/org.stagecraft.player.it,tests/org.stagecraft.demo.it "-Dstagecraft.playerStage=$prefix")
  [ -z "$python" ] || args+=("-Dstagecraft.python=$python")
  say "running the real Player/Stage tier: ./mvnw ${args[*]} $*"
  local rc=0
  (cd "$root" && ./mvnw "${args[@]}" "$@") || rc=$?
  local tests=0 failures=0 errors=0 skipped=0 f v n
  shopt -s nullglob
  for f in "$reports"/TEST-*.xml "$demo_reports"/TEST-*.xml; do
    for v in tests failures errors skipped; do
      n=$(sed -n "s/.*<testsuite[^>]* $v=\"\([0-9]*\)\".*/\1/p" "$f" | head -1)
      eval "$v=\$(( $v + ${n:-0} ))"
    done
  done
  shopt -u nullglob
  echo "stagecraft: real Player/Stage tier: $tests tests, $failures failures, $errors errors, $skipped skipped ($((SECONDS - t0)) s; reports in $reports and $demo_reports)" >&2
  [ "$rc" = 0 ] || die "the real Player/Stage tier failed (Maven exit code $rc)"
  [ "$tests" -gt 0 ] || die "the real Player/Stage tier ran no test"
  [ "$skipped" = 0 ] || die "the real Player/Stage tier skipped $skipped tests: a skipped test does not pass"
}

usage() {
  awk 'NR > 1 && /^#/ { sub(/^# ?/, ""); print; next } NR > 1 { exit }' "$0"
}

case "${1:-}" in
  install) shift; cmd_install "$@" ;;
  env) shift; cmd_env "$@" ;;
  tier) shift; cmd_tier "$@" ;;
  ""|-h|--help|help) usage ;;
  *) die "unknown command '$1' (install, env, tier)" ;;
esac
