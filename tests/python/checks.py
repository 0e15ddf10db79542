"""The check harness of the Python unit tests in this folder: check()
prints a named result and records a failure, finish() prints the outcome
and exits with the test's status (1 if any check failed)."""
import sys

fails = []


def check(name, ok, detail=""):
    print("%-70s %s  %s" % (name, "ok" if ok else "FAILED", detail))
    if not ok:
        fails.append(name)


def finish():
    print("PASS" if not fails else "FAIL: %d check(s): %s" % (len(fails), ", ".join(fails)))
    sys.exit(1 if fails else 0)
