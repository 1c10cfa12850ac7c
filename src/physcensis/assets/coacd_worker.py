"""Run CoACD on one mesh in a child process: an .npz request on stdin, an .npz of parts on stdout.

Started by `decompose.py` as a plain script (`python coacd_worker.py`), so it imports only numpy and coacd:
the child starts in a fraction of a second and can be killed when it overruns its time.
"""

from __future__ import annotations

import io
import json
import sys

import numpy as np


def decompose(request: bytes) -> bytes:
    import coacd

    with np.load(io.BytesIO(request), allow_pickle=False) as npz:
        vertices, faces = np.asarray(npz["vertices"], dtype=np.float64), np.asarray(npz["faces"], dtype=np.int32)
        settings = json.loads(npz["settings"].tobytes().decode())
    coacd.set_log_level("error")
    parts = coacd.run_coacd(coacd.Mesh(vertices, faces), **settings)
    arrays = {f"part_{i}": np.asarray(v, dtype=np.float64).reshape(-1, 3) for i, (v, _f) in enumerate(parts)}
    buffer = io.BytesIO()
    np.savez(buffer, count=np.array(len(arrays)), **arrays)  # type: ignore[arg-type]
    return buffer.getvalue()


def main() -> int:
    try:
        answer = decompose(sys.stdin.buffer.read())
    except ImportError:
        sys.stderr.write("convex decomposition of concave meshes needs the package coacd (pip install coacd)\n")
        return 2
    except Exception as exc:  # CoACD gives up on some meshes: say why on stderr
        sys.stderr.write(f"{type(exc).__name__}: {exc}\n")
        return 1
    sys.stdout.buffer.write(answer)
    return 0


if __name__ == "__main__":
    sys.exit(main())
