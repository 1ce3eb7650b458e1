# The helpers of the tmux end-to-end tests, sourced by console.sh and
# trust.sh after they set `bin` and `case`: a private tmux server (-L), no
# tmux configuration (-f /dev/null), an isolated HOME and XDG directories,
# LANG=C.UTF-8. Every wait polls the screen with a timeout; a failure prints
# the screen.
# SPDX-License-Identifier: GPL-3.0-or-later
command -v tmux >/dev/null || { echo "tmux is not installed (scripts/test installs it)"; exit 77; }

work=$(mktemp -d)
sock="pupitre-e2e-$$-$case"
T() { tmux -L "$sock" "$@"; }
cleanup() { T kill-server 2>/dev/null; rm -rf "$work"; }
trap cleanup EXIT
export HOME=$work/home XDG_DATA_HOME=$work/data XDG_CONFIG_HOME=$work/config
mkdir -p "$HOME"

screen() { T capture-pane -p -t e2e 2>/dev/null; }
# The screen with its SGR colour and attribute sequences (capture-pane -e).
screen_e() { T capture-pane -e -p -t e2e 2>/dev/null; }
# sgr_line REGEX: the coloured capture of the first line matching REGEX.
sgr_line() { screen_e | grep -E -m1 -- "$1"; }
fail() {
    echo "FAIL ($case): $*"
    echo "---- screen ----"
    screen
    echo "----------------"
    exit 1
}
# wait_for REGEX [SECONDS]: polls the screen until a line matches.
wait_for() {
    local re=$1 limit=${2:-10} i
    for ((i = 0; i < limit * 20; i++)); do
        screen | grep -Eq -- "$re" && return 0
        sleep 0.05
    done
    fail "waited ${limit}s for /$re/"
}
# The message line (above the input line), and expect_message REGEX, which
# polls it (a loaded machine may take a moment to answer) for 5 s.
message() { screen | tail -3 | head -1; }
expect_message() {
    local i
    for ((i = 0; i < 100; i++)); do
        message | grep -Eq -- "$1" && return 0
        sleep 0.05
    done
    fail "message: expected /$1/"
}
keys() { T send-keys -t e2e "$@"; }
# stty_after: waits until the pane wrote the terminal modes after the console
# ended (the line runs `echo EXIT=...` first, then `stty -a`).
stty_after() {
    local i
    for ((i = 0; i < 100; i++)); do
        [ -s "$work/stty" ] && return 0
        sleep 0.05
    done
    fail "the terminal modes were not written after the console ended"
}
# A second session gets a server of its own: a new one on the old socket can
# race with the old one's exit ("server exited unexpectedly").
next_server() {
    T kill-server 2>/dev/null
    sock="$sock+"
}
# cmd TEXT: a ':' command typed on the input line.
cmd() { keys -l "$1"; keys Enter; sleep 0.1; }
start() {
    rm -f "$work/stty"  # this session's modes, not an earlier one's
    # After the console: its exit status and the terminal modes, to check that
    # the terminal was given back as it was.
    T -f /dev/null new-session -d -s e2e -x "${W:-80}" -y "${H:-24}" \
        "env LANG=C.UTF-8 TERM=screen ${E2E_ENV:-} '$bin' $* ; echo EXIT=\$? ; stty -a > '$work/stty' ; sleep 30"
    wait_for 'F1 help|1HELP|1AIDE' 10
}
# A second console beside the first (session e2f), as two PCs of a class on
# one store: start2 ARGS, screen2, wait2 REGEX [SECONDS], keys2, cmd2.
start2() {
    T -f /dev/null new-session -d -s e2f -x 80 -y 24 \
        "env LANG=C.UTF-8 TERM=screen '$bin' $* ; echo EXIT=\$? ; sleep 30"
}
screen2() { T capture-pane -p -t e2f 2>/dev/null; }
wait2() {
    local i
    for ((i = 0; i < ${2:-10} * 20; i++)); do
        screen2 | grep -Eq -- "$1" && return 0
        sleep 0.05
    done
    echo "---- second console ----"
    screen2
    fail "the second console waited for /$1/"
}
keys2() { T send-keys -t e2f "$@"; }
cmd2() { keys2 -l "$1"; keys2 Enter; sleep 0.1; }
pom() {
    cmd ":mode pom"
    keys F9
    wait_for '^ POM .*READY' 20
}
# The value shown on the OP page for an axis ("  Xø      150.000 ...").
op_value() { screen | awk -v a="$1" '$1 == a || $1 == a"ø" { print $2; exit }'; }

