# Shared by scripts/run, scripts/test and scripts/bench: install the Debian
# packages pupitre needs when they are missing (sudo when not root).
# SPDX-License-Identifier: GPL-3.0-or-later

# Packages to build and run pupitre.
PUPITRE_BUILD_DEPS=(cmake g++ make pkg-config libeigen3-dev libcli11-dev libsqlite3-dev libpq-dev libssl-dev libncurses-dev libreadline-dev libcairo2-dev libpng-dev libpolyclipping-dev libchafa-dev gettext)
# Packages the test suite adds (sqlite3 and util-linux's setpriv: the store's
# anomaly tests make damaged files and drop root to meet a read-only directory).
PUPITRE_TEST_DEPS=(locales libgtest-dev libgmock-dev clang clang-format libclang-rt-14-dev groff-base python3 sqlite3 util-linux tmux valgrind)
# The throwaway server the store's tests also run against (scripts/lib/pg.sh).
PUPITRE_PG_DEPS=(postgresql openssl)

ensure_packages() {
    local missing=() p
    for p in "$@"; do
        dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
    done
    [ ${#missing[@]} -eq 0 ] && return 0
    local sudo=""
    [ "$(id -u)" = 0 ] || sudo=sudo
    echo "Installing missing Debian packages: ${missing[*]}" >&2
    $sudo apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >&2
}
