#!/usr/bin/env bash
# The web front end's build and tests (web/ → src/eigendance/static/), called by the Makefile.
#   scripts/web.sh install   npm ci (once per package-lock.json)
#   scripts/web.sh build     type-check and build into the package (the build is also committed,
#                            so a wheel and `pip install` never need Node), then stamp it
#                            (scripts/web_stamp.py: tests/web/test_web_build_fresh.py then fails
#                            when web/src or the lock file changed since)
#   scripts/web.sh test      Vitest unit tests
# Vite 7 needs Node >= 20.19: with an older Node (or no npm) the committed build is kept and the
# Vitest tests are skipped with a warning (the Python and browser tests still run) — except
# under CI (the CI environment variable set and not empty), where that fails the run (exit 1).
set -euo pipefail
cd "$(dirname "$0")/../web"
task="${1:-}"
node_ok() {
  command -v node >/dev/null 2>&1 && command -v npm >/dev/null 2>&1 &&
    node -e 'const [a,b]=process.versions.node.split(".").map(Number); process.exit(a>20||a===20&&b>=19?0:1)'
}
case "$task" in
  install|build|test) ;;
  *) echo "usage: scripts/web.sh install|build|test" >&2; exit 2 ;;
esac
if ! node_ok; then
  if [ -n "${CI:-}" ]; then
    echo "web: Node >= 20.19 with npm not found; under CI '$task' cannot be skipped" >&2
    exit 1
  fi
  echo "web: Node >= 20.19 with npm not found; keeping the committed build, skipping '$task'" >&2
  exit 0
fi
case "$task" in
  install)
    if [ ! -f node_modules/.installed ] || [ package-lock.json -nt node_modules/.installed ]; then
      # npm 11 can write lock files without other platforms' optional packages (rollup,
      # esbuild), which `npm ci` then rejects; `npm install` from the same lock works.
      npm ci --no-audit --no-fund --loglevel=error 2>/dev/null ||
        npm install --no-audit --no-fund --no-save --loglevel=error
      touch node_modules/.installed
    fi ;;
  build)
    npx --no-install tsc --noEmit
    npx --no-install vite build --logLevel warn
    # after the build: vite's emptyOutDir wipes src/eigendance/static, stamp included
    "${PYTHON:-python3}" ../scripts/web_stamp.py write ;;
  test)
    npx --no-install vitest run ;;
esac
