#!/usr/bin/env python3
"""Submits a scene to radiantd, prints its progress, then the work-plane table.

    python3 first_solve.py SCENE.json [--server URL] [--tolerance X]

The server defaults to $RADIANT_SERVER, else http://127.0.0.1:8080 (as for the radiant CLI).
Exit status: 0 when the job is done, 2 when the scene is refused (one line per problem, as
`radiant validate` prints them), 1 otherwise.
"""

import argparse
import sys

from radiant_client import Client, JobFailedError, RadiantError, SceneError


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("scene", help="radiant-scene/1 JSON file")
    parser.add_argument("--server", help="radiantd base URL")
    parser.add_argument("--tolerance", type=float, help="override the scene's tolerance")
    args = parser.parse_args()

    client = Client(args.server)
    settings = {"tolerance": args.tolerance} if args.tolerance else None
    try:
        job = client.submit(args.scene, settings)
        print(f"job {job.id}")

        def progress(p: dict) -> None:
            # The error is null until the solver has an estimate.
            error = p.get("error_estimate")
            shown = "—" if error is None else f"{error:.1e}"
            print(f"{100 * p['fraction']:5.1f}%  {p.get('stage', ''):<14} "
                  f"iterations {p['iterations']:<4} error {shown:>7}  "
                  f"{p['elapsed_seconds']:.1f} s", flush=True)

        final = job.wait(progress=progress)
        result = job.result()
        print(f"{final['status']}: {result['status']} in {result['stats'].get('seconds', 0):.1f} s")
        print()
        print(job.table(result))
        return 0 if final["status"] == "done" else 1
    except SceneError as e:
        for problem in e.problems:
            print(f"{args.scene}: {problem.pointer}: {problem.message}", file=sys.stderr)
        return 2
    except JobFailedError as e:
        print(e, file=sys.stderr)
        return 1
    except RadiantError as e:
        print(f"{client.url}: {e}", file=sys.stderr)
        return 1


if __name__ == "__main__":
    sys.exit(main())
