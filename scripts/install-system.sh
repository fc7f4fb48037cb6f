#!/usr/bin/env bash
# System packages eigendance's tests need on a fresh Debian machine: Chromium for the browser
# tests (Playwright drives /usr/bin/chromium; it cannot download its own browser here) and the
# venv module. Installs only what is missing; uses sudo when not root.
set -euo pipefail
packages=()
command -v chromium >/dev/null 2>&1 || packages+=(chromium libatomic1)
python3 -c 'import venv, ensurepip' >/dev/null 2>&1 || packages+=(python3-venv)
command -v node >/dev/null 2>&1 || packages+=(nodejs npm)
if [ ${#packages[@]} -gt 0 ]; then
  sudo=""; [ "$(id -u)" -eq 0 ] || sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq "${packages[@]}" >/dev/null
fi
