# args.sh - sourced by the tests' scripts that a learner may run by hand: their usage, and the
# folders they write.
#   args_expect COUNT "$@"
#       prints the calling script's usage (its header comment, up to the first line that is not a
#       comment) and exits 2 when asked for --help, or when the arguments are not COUNT paths (an
#       option such as --tile 16 is refused: these scripts take none)
#   args_fresh_dir DIR
#       makes DIR empty for the script's output: a folder this script family made before (it holds
#       the mark .course-test-output) is emptied; an empty or missing one is made and marked; any
#       other path is refused (exit 2) and left as it is, so a mistyped argument cannot delete a
#       learner's folder

args_usage() {
    sed -n '2,/^[^#]/{/^#/s/^# \{0,1\}//p}' "$0" >&2
}

args_expect() {
    local count=$1 a
    shift
    for a in "$@"; do
        case $a in
          -h | --help) args_usage; exit 2 ;;
          -*) echo "$(basename "$0"): unknown option '$a'; it takes $count path(s):" >&2; args_usage; exit 2 ;;
        esac
    done
    if [ $# -ne "$count" ]; then
        echo "$(basename "$0"): $# argument(s) given, $count expected:" >&2
        args_usage
        exit 2
    fi
}

args_fresh_dir() {
    local dir=$1
    if [ -e "$dir" ] && [ ! -e "$dir/.course-test-output" ] && [ -n "$(ls -A "$dir" 2>/dev/null)" ]; then
        echo "$(basename "$0"): $dir exists and was not made by a course test; give a new folder" >&2
        exit 2
    fi
    if [ -e "$dir" ] && [ ! -d "$dir" ]; then
        echo "$(basename "$0"): $dir is not a folder; give a new folder" >&2
        exit 2
    fi
    rm -rf "$dir" && mkdir -p "$dir" && touch "$dir/.course-test-output"
}
