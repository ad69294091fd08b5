"""The tally of a test script's checks (tests/io/*.py): check() records each, finish() prints the
failures and the closing 'N passed, M failed' line and gives the script's exit code."""

failures = []
passed = 0


def check(name, ok, detail=""):
    global passed
    if ok:
        passed += 1
    else:
        failures.append(f"{name}: {detail}")


def finish():
    """Prints the failures and the tally; 1 if any check failed, else 0."""
    for f in failures:
        print("FAILED: " + f[:3000])
    print(f"{passed} passed, {len(failures)} failed")
    return 1 if failures else 0
