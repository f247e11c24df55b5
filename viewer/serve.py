#!/usr/bin/python3
"""The local HTTP server of the OpenMSS viewer (docs/viewer.md).

Serves, on 127.0.0.1 only, the page and its modules from --root, the model's scene as
/scene.json and the results file as /result.res. `openmss view` writes the scene and starts
this server; it also runs directly:

    /usr/bin/python3 build/viewer/serve.py --root build/viewer --scene S.json --result R.res

Prints "OpenMSS viewer: http://127.0.0.1:PORT/" once it listens (PORT 0: a free port).
Nothing here reaches the network beyond the loopback interface.
"""

import argparse
import functools
import http.server
import os
import shutil
import signal
import sys

# The only files served: the page's own, and the two data files under fixed names.
STATIC = {
    "/": "index.html",
    "/index.html": "index.html",
    "/viewer.js": "viewer.js",
    "/res_reader.js": "res_reader.js",
    "/scene_builder.js": "scene_builder.js",
    "/plot.js": "plot.js",
    "/OrbitControls.js": "OrbitControls.js",
    "/three.module.js": "three.module.js",
    "/three.core.js": "three.core.js",
}
TYPES = {".html": "text/html; charset=utf-8", ".js": "text/javascript; charset=utf-8",
         ".json": "application/json", ".res": "application/xml"}


class Handler(http.server.BaseHTTPRequestHandler):
    def __init__(self, files, *args, **kwargs):
        self.files = files
        super().__init__(*args, **kwargs)

    def do_GET(self):  # noqa: N802 (the http.server name)
        path = self.path.split("?", 1)[0]
        file = self.files.get(path)
        if file is None or not os.path.isfile(file):
            self.send_error(404, "not served: " + path)
            return
        with open(file, "rb") as f:
            body = f.read()
        self.send_response(200)
        self.send_header("Content-Type", TYPES.get(os.path.splitext(file)[1], "text/plain"))
        self.send_header("Content-Length", str(len(body)))
        self.send_header("Cache-Control", "no-store")
        self.end_headers()
        self.wfile.write(body)

    def log_message(self, *args):  # quiet: the URL line is the only output
        pass


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--root", required=True, help="folder of index.html and the modules")
    p.add_argument("--scene", required=True, help="scene.json written by openmss view")
    p.add_argument("--result", required=True, help="the .res file")
    p.add_argument("--port", type=int, default=0, help="port on 127.0.0.1 (0: a free one)")
    p.add_argument("--temporary", action="store_true",
                   help="the scene's folder is temporary: removed when the server stops")
    a = p.parse_args(argv)
    files = {url: os.path.join(a.root, name) for url, name in STATIC.items()}
    files["/scene.json"] = a.scene
    files["/result.res"] = a.result
    server = http.server.ThreadingHTTPServer(("127.0.0.1", a.port),
                                             functools.partial(Handler, files))
    print("OpenMSS viewer: http://127.0.0.1:%d/" % server.server_address[1], flush=True)
    # Ctrl-C and a plain kill both stop the server through the same path.
    signal.signal(signal.SIGTERM, lambda *_: (_ for _ in ()).throw(KeyboardInterrupt()))
    try:
        server.serve_forever()
    except KeyboardInterrupt:
        pass
    finally:
        server.server_close()
        if a.temporary:
            shutil.rmtree(os.path.dirname(os.path.abspath(a.scene)), ignore_errors=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
