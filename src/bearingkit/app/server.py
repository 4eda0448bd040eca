"""Run the web app: uvicorn on 127.0.0.1 unless a host is given on purpose (then with a warning).

SI inside (nothing here computes). :func:`serve` is what ``bearingkit serve`` calls; it blocks until
Ctrl+C and removes the server's temporary folder on the way out.
"""

from __future__ import annotations

import ipaddress
import socket
import sys
import threading
import webbrowser

from bearingkit.errors import InputError

__all__ = ["DEFAULT_HOST", "DEFAULT_PORT", "is_loopback", "serve"]

DEFAULT_HOST = "127.0.0.1"
DEFAULT_PORT = 8765


def is_loopback(host: str) -> bool:
    """True for 127.0.0.0/8, ::1 and ``localhost``."""
    if host == "localhost":
        return True
    try:
        return ipaddress.ip_address(host.strip("[]")).is_loopback
    except ValueError:
        return False


def _check_port(host: str, port: int) -> None:
    """One line instead of uvicorn's traceback-like exit when the port is taken or the host unknown."""
    if not 0 < port < 65536:
        raise InputError(f"--port ({port}) must lie in 1 … 65535")
    try:
        infos = socket.getaddrinfo(host, port, type=socket.SOCK_STREAM)
    except socket.gaierror:
        raise InputError(f"--host ({host!r}) is not an address of this machine") from None
    family, _, _, _, address = infos[0]
    with socket.socket(family, socket.SOCK_STREAM) as s:
        s.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
        try:
            s.bind(address)
        except OSError as exc:
            raise InputError(
                f"--port ({port}) cannot be used on {host} ({exc.strerror}); give another, "
                f"e.g. --port {port + 1}"
            ) from None


def serve(host: str = DEFAULT_HOST, port: int = DEFAULT_PORT, open_browser: bool = False, echo=print) -> None:
    """Serve the app until interrupted.

    Parameters
    ----------
    host : str
        Address to bind; a non-loopback one exposes the app to the network (printed warning; there is
        no login).
    port : int
    open_browser : bool
        Open the page in the default browser once the server listens.
    echo : callable
        Where the start-up lines go.
    """
    import uvicorn

    from bearingkit.app.api import LOOPBACK_HOSTS, create_app
    from bearingkit.app.store import Store

    _check_port(host, port)
    loopback = is_loopback(host)
    if not loopback:
        sys.stderr.write(
            f"warning: serving on {host}: anyone who can reach this machine on port {port} can use the app "
            "(there is no login); bind to 127.0.0.1 (the default) unless you mean it\n"
        )
    shown = f"[{host}]" if ":" in host else host
    url = f"http://{'127.0.0.1' if host in ('0.0.0.0', '::') else shown}:{port}/"
    store = Store()
    app = create_app(store, allowed_hosts=LOOPBACK_HOSTS if loopback else ("*",), warm=True)
    config = uvicorn.Config(app, host=host, port=port, log_level="warning", server_header=False)
    server = uvicorn.Server(config)
    echo(f"bearingkit serve: {url}  (Ctrl+C to stop)")
    if open_browser:

        def opener():
            while not server.started and not server.should_exit:
                threading.Event().wait(0.05)
            if server.started:
                webbrowser.open(url)

        threading.Thread(target=opener, daemon=True).start()
    try:
        server.run()
    finally:  # also when the server stops without its shutdown (a second Ctrl+C)
        store.close()
