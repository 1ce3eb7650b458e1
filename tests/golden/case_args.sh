# Sourced by golden.sh, tests/plot/plot.sh and tests/i18n/golden_fr.sh: the
# machine and the program arguments of one case of $here/cases.txt (needs
# $here, $root and $shared). Arguments: shared:F (../shared/programs), local:F
# (tests/golden/programs), bad:F (tests/bad), plot:F (tests/plot/programs).
#   golden_case NAME   sets $machine and the array $args (exit 77: shared/ missing)
# SPDX-License-Identifier: GPL-3.0-or-later
golden_case() {
    local name=$1 line w f rest
    line=$(grep -E "^$name[[:space:]]" "$here/cases.txt" || true)
    [ -n "$line" ] || { echo "golden: no case '$name' in cases.txt" >&2; exit 2; }
    read -r _ machine rest <<<"$line"
    args=()
    for w in $rest; do
        case $w in
            shared:*) f="$shared/programs/${w#shared:}"
                      [ -f "$f" ] || { echo "golden: $f missing (shared/ not beside the repo)" >&2; exit 77; }
                      args+=("$f") ;;
            local:*)  args+=("$root/tests/golden/programs/${w#local:}") ;;
            bad:*)    args+=("$root/tests/bad/${w#bad:}") ;;
            plot:*)   args+=("$root/tests/plot/programs/${w#plot:}") ;;
            *)        args+=("$w") ;;
        esac
    done
}
