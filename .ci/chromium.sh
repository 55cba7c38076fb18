#!/usr/bin/env bash
# Debian's chromium for the page's end-to-end test (tests/views/page/test_page_e2e.py drives it
# through Playwright with executable_path=/usr/bin/chromium; Playwright's own browser
# builds are never downloaded). Installs it with apt-get when it is missing and we are
# root (CI runs as root on Debian); otherwise says what is missing and leaves it: the
# e2e test then fails with that message, it does not skip.
set -uo pipefail
CHROMIUM=${ASSUR_CHROMIUM:-/usr/bin/chromium}
if [ -x "$CHROMIUM" ]; then
    exit 0
fi
if [ "$(id -u)" != 0 ] || ! command -v apt-get >/dev/null 2>&1; then
    echo "warning: $CHROMIUM is missing and cannot be installed here (needs root and" \
         "apt-get): install Debian's chromium package for tests/views/page/test_page_e2e.py" >&2
    exit 0
fi
echo "installing chromium (apt-get) for the page's end-to-end test" >&2
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq >/dev/null && \
    apt-get install -y -qq --no-install-recommends chromium fonts-dejavu-core >/dev/null || {
    echo "warning: apt-get could not install chromium" >&2
    exit 0
}
