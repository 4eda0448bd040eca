#!/bin/sh
# Debian's headless Chromium (and its driver) for the browser tests: the HTML report is rendered and
# screenshotted in a real browser, and the web app is driven in one. Installed only when missing;
# says what it will do, and why, before it does it. Without root it installs nothing and says how to.
set -eu
CHROMIUM=/usr/bin/chromium
DRIVER=/usr/bin/chromedriver
PACKAGES="chromium chromium-driver"
if [ -x "$CHROMIUM" ] && [ -x "$DRIVER" ]; then
    echo "ensure_chromium: $("$CHROMIUM" --version 2>/dev/null || echo chromium) and chromedriver present; nothing to do"
    exit 0
fi
echo "ensure_chromium: the browser tests (HTML report, web app) need Debian's $PACKAGES, which are missing."
if [ "$(id -u)" -ne 0 ]; then
    echo "ensure_chromium: not root, so nothing is installed; the browser tests will fail until you run:"
    echo "ensure_chromium:     sudo apt-get update && sudo apt-get install -y $PACKAGES"
    exit 0
fi
echo "ensure_chromium: installing them now with apt-get (about 70 s and ~250 MB; apt also pulls in"
echo "ensure_chromium: their dependencies, e.g. fonts and systemd/cups libraries). Nothing else is changed."
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
apt-get install -y -qq $PACKAGES >/dev/null
echo "ensure_chromium: installed $("$CHROMIUM" --version 2>/dev/null || echo chromium)"
