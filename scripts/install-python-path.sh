#!/usr/bin/env bash
# Makes the built Python package importable by Debian's /usr/bin/python3 from any folder: writes
# openmss.pth, naming <checkout>/build/python, into the interpreter's site directory
# (/usr/local/lib/python3.11/dist-packages on Debian 12; as root, or with sudo, as
# install-deps.sh does). Run by run-example.sh and test.sh after the build; safe to run again.
# OPENMSS_SITE_DIR overrides the directory (the tests use a scratch folder). docs/python.md.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
python=${OPENMSS_PYTHON:-/usr/bin/python3}
site=${OPENMSS_SITE_DIR:-$("$python" -c 'import site; print(site.getsitepackages()[0])')}
line="$root/build/python"
pth="$site/openmss.pth"
if [[ -f $pth && $(cat "$pth") == "$line" ]]; then
  echo "install-python-path: $pth already names $line"
  exit 0
fi
sudo_cmd=()
writable=$site
[[ -d $site ]] || writable=$(dirname "$site")
if [[ $(id -u) -ne 0 && ! -w $writable ]]; then sudo_cmd=(sudo); fi
"${sudo_cmd[@]}" mkdir -p "$site"
printf '%s\n' "$line" | "${sudo_cmd[@]}" tee "$pth" >/dev/null
echo "install-python-path: wrote $pth -> $line"
