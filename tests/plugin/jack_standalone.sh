#!/bin/sh
# The JACK standalone in a real JACK server (jackd2, dummy driver, a server name of its own so
# parallel tests never meet): it connects as a client with the plugin's ports, two music inputs,
# two vibration outputs and the two delayed music outputs; everything started is stopped. Its
# stderr is kept: a sanitizer's report there (make test-tsan) fails the test.
# Usage: jack_standalone.sh tactus-jack
set -u
program=$1
server=tactus-test-$$
jackd -n "$server" -d dummy -r 44100 -p 256 >/dev/null 2>&1 &
jackd_pid=$!
plugin_pid=
log=$(mktemp)
cleanup() {
    [ -n "$plugin_pid" ] && kill "$plugin_pid" 2>/dev/null && wait "$plugin_pid" 2>/dev/null
    kill "$jackd_pid" 2>/dev/null && wait "$jackd_pid" 2>/dev/null
    plugin_pid=
    jackd_pid=
}
trap 'cleanup; rm -f "$log"' EXIT
jack_wait -s "$server" -w -t 10 >/dev/null || { echo "jackd did not start" >&2; exit 1; }
JACK_DEFAULT_SERVER=$server "$program" >/dev/null 2>"$log" &
plugin_pid=$!
expected="tactus:music_l tactus:music_r tactus:vibration_1 tactus:vibration_2 tactus:music_out_l tactus:music_out_r"
for _ in $(seq 50); do
    ports=$(jack_lsp -s "$server" 2>/dev/null)
    missing=
    for port in $expected; do echo "$ports" | grep -qx "$port" || missing="$missing $port"; done
    [ -z "$missing" ] && break
    sleep 0.2
done
echo "$ports"
[ -z "$missing" ] || { echo "missing ports:$missing" >&2; exit 1; }
kill -0 "$plugin_pid" || { cat "$log"; echo "$program exited" >&2; exit 1; }
cleanup
if grep -q "Sanitizer" "$log"; then cat "$log"; exit 1; fi
echo "tactus-jack runs with its ports on JACK server $server"
