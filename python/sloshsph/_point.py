"""One point of a sweep, in its own process: ``python -m sloshsph._point`` reads the job (JSON) on
stdin, runs or resumes it, and exits with the program's exit code."""

import json
import sys

from . import _core
from .errors import CaseError


def main():
    job = json.loads(sys.stdin.read())
    try:
        if job["resume"]:
            code = _core.resume_run(job["directory"], job["threads"], 0.0, "python: sloshsph.sweep (point, resumed)", None)
        else:
            code = _core.run_case(job["text"], job["source"], job["name"], job["overrides"], job["directory"],
                                  job["force"], job["threads"], 0.0, "python: sloshsph.sweep (point)", None)
    except CaseError as e:
        sys.stderr.write(f"sloshsph: error: {e}\n")
        code = 2
    return code


if __name__ == "__main__":
    sys.exit(main())
