#!/bin/sh
# Install Debian's chromium (for the headless-browser test of the HTML report) only when it is missing.
# Run as root (Makefile/CI); non-interactive. Prints what it did.
set -eu
CHROMIUM=/usr/bin/chromium
if [ -x "$CHROMIUM" ]; then
    echo "ensure_chromium: $CHROMIUM present ($("$CHROMIUM" --version 2>/dev/null || echo 'version unknown')); nothing to do"
    exit 0
fi
if [ "$(id -u)" -ne 0 ]; then
    echo "ensure_chromium: $CHROMIUM missing and not root; run as root: apt-get update && apt-get install -y chromium" >&2
    exit 1
fi
echo "ensure_chromium: $CHROMIUM missing; running apt-get update && apt-get install -y chromium"
export DEBIAN_FRONTEND=noninteractive
apt-get update
apt-get install -y chromium
echo "ensure_chromium: installed $("$CHROMIUM" --version 2>/dev/null || echo chromium)"
