#!/usr/bin/env bash
# Run a Gradescope autograder bundle the way Gradescope does, on this machine:
# in a private mount namespace with its own /autograder tree (source,
# submission, results), an empty /opt, a clean environment, as root. setup.sh
# runs once, then run_autograder once per upload.
#
#   unshare -m --propagation private bash gradescope_simulation.sh BUNDLE UPLOADS OUT
#
# BUNDLE: the folder `turtletui autograder gradescope` wrote; UPLOADS: one folder
# per upload, whose contents become /autograder/submission; OUT: gets
# NAME.json (the results.json of upload NAME) and setup.log.
set -euo pipefail
bundle=$(realpath "$1"); uploads=$(realpath "$2"); out=$(realpath "$3")
mkdir -p "$out"

# our own /autograder and an empty /opt, seen only in this namespace
mkdir -p /autograder
mount -t tmpfs -o mode=755 autograder /autograder
mount -t tmpfs -o mode=755 opt /opt
mkdir -p /autograder/source /autograder/submission /autograder/results
cp -r "$bundle"/. /autograder/source/
cp /autograder/source/run_autograder /autograder/run_autograder
chmod +x /autograder/run_autograder

clean_env=(env -i PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin HOME=/root LANG=C.UTF-8)
if ! (cd /autograder/source && "${clean_env[@]}" bash ./setup.sh) >"$out/setup.log" 2>&1; then
    echo "setup.sh failed; see $out/setup.log" >&2
    exit 1
fi

for upload in "$uploads"/*/; do
    name=$(basename "$upload")
    find /autograder/submission /autograder/results -mindepth 1 -delete
    cp -r "$upload". /autograder/submission/
    (cd /autograder && "${clean_env[@]}" timeout 600 /autograder/run_autograder) >"$out/$name.log" 2>&1 || true
    if [ -f /autograder/results/results.json ]; then
        cp /autograder/results/results.json "$out/$name.json"
    fi
done
