#!/usr/bin/env bash
# tools/fresh_clone_check.sh [--root-only | --user-only] [--keep] [COMMIT]
#
# Runs `make test` as a new user would: in a fresh clone of this repository's COMMIT (default
# HEAD) made in a private folder (mktemp -d, mode 0700),
#   1. as root, and
#   2. as a freshly created unprivileged user whose home is mode 0700, who may install nothing:
#      first `scripts/install-deps.sh` is checked to name a missing package and stop (exit 1,
#      the apt-get command to run) without installing it, then `make test` runs with the
#      packages root installed before.
# Run it as root (it creates and removes the user). Logs go to $TMPDIR (default /tmp),
# fresh-clone-root.log and fresh-clone-user.log; it prints a line per step and exits 1 at the
# first step that fails. --keep leaves the clones and the user in place for a look.
set -euo pipefail

mode=both keep=0 commit=HEAD
for arg in "$@"; do
    case $arg in
        --root-only) mode=root ;;
        --user-only) mode=user ;;
        --keep) keep=1 ;;
        -h|--help) sed -n '2,15p' "$0"; exit 0 ;;
        *) commit=$arg ;;
    esac
done
[[ "$(id -u)" -eq 0 ]] || { echo "fresh_clone_check: run it as root (it creates a user)" >&2; exit 2; }

repo=$(git -C "$(dirname "$0")/.." rev-parse --show-toplevel)
sha=$(git -C "$repo" rev-parse --verify "$commit^{commit}")
logs=${TMPDIR:-/tmp}
user=fpmcheck$$
cleanup=()
finish() {
    if [[ $keep -eq 0 ]]; then
        for path in "${cleanup[@]}"; do rm -rf "$path"; done
        id "$user" >/dev/null 2>&1 && userdel -r "$user" >/dev/null 2>&1 || true
    fi
}
trap finish EXIT

# The commit as a bundle in a folder every user can read: the repository itself may lie in a
# folder the new user cannot enter.
share=$(mktemp -d)
chmod 0755 "$share"
cleanup+=("$share")
git init --quiet --bare "$share/refs.git"
git -C "$share/refs.git" fetch --quiet "$repo" "$sha:refs/heads/fresh-clone-check"
git -C "$share/refs.git" bundle create --quiet "$share/fpmshell.bundle" fresh-clone-check
rm -rf "$share/refs.git"
chmod 0644 "$share/fpmshell.bundle"
echo "fresh_clone_check: commit $sha"

# clone_and_test: in a new private folder of the caller, clone the bundle and run make test.
clone_and_test='set -euo pipefail
    private=$(mktemp -d)          # mode 0700, as mktemp makes it
    echo "clone in $private (mode $(stat -c %a "$private"))"
    git clone --quiet --branch fresh-clone-check "$1" "$private/fpmshell"
    cd "$private/fpmshell"
    make test'

if [[ $mode != user ]]; then
    echo "fresh_clone_check: make test as root (log $logs/fresh-clone-root.log)"
    if ! bash -c "$clone_and_test" _ "$share/fpmshell.bundle" >"$logs/fresh-clone-root.log" 2>&1; then
        tail -30 "$logs/fresh-clone-root.log"
        echo "fresh_clone_check: FAILED as root" >&2
        exit 1
    fi
    grep -E 'tests passed|tests failed' "$logs/fresh-clone-root.log" | tail -1
    cleanup+=("$(sed -n 's/^clone in \([^ ]*\) .*/\1/p' "$logs/fresh-clone-root.log")")
fi

if [[ $mode != root ]]; then
    useradd --create-home --shell /bin/bash "$user"
    home=$(getent passwd "$user" | cut -d: -f6)
    chmod 0700 "$home"
    echo "fresh_clone_check: user $user, home $home (mode $(stat -c %a "$home"))"
    as_user() { runuser -u "$user" -- env -i HOME="$home" USER="$user" LOGNAME="$user" \
                    PATH=/usr/local/bin:/usr/bin:/bin TMPDIR="$home" bash -c "$@"; }

    # The user may install nothing: a missing package is named with the command to install it.
    probe=fpmshell-fresh-clone-missing-package
    set +e
    out=$(as_user 'cd "$(mktemp -d)" && git clone --quiet --branch fresh-clone-check "$1" f &&
                   f/scripts/install-deps.sh "$2" 2>&1' _ "$share/fpmshell.bundle" "$probe")
    status=$?
    set -e
    if [[ $status -ne 1 ]] || ! grep -q "missing Debian packages: $probe" <<<"$out" ||
       ! grep -q "sudo apt-get install -y $probe" <<<"$out"; then
        echo "$out"
        echo "fresh_clone_check: FAILED: install-deps.sh as a user did not name the missing package and stop (exit $status)" >&2
        exit 1
    fi
    echo "install-deps.sh as $user: names the missing package, exit 1"

    echo "fresh_clone_check: make test as $user (log $logs/fresh-clone-user.log)"
    if ! as_user "$clone_and_test" _ "$share/fpmshell.bundle" >"$logs/fresh-clone-user.log" 2>&1; then
        tail -30 "$logs/fresh-clone-user.log"
        echo "fresh_clone_check: FAILED as $user" >&2
        exit 1
    fi
    grep -E 'tests passed|tests failed' "$logs/fresh-clone-user.log" | tail -1
fi
echo "fresh_clone_check: make test passed on fresh clones of $sha"
