"""Many `pita eval` calls in a few processes, through `pita eval --batch -`.

Each request is the argument list of one `pita eval`; each answer has the returncode, stdout
and stderr that the separate call would have had (the CLI tests check this byte for byte,
tests/cli/test_eval_batch.cpp).  The comparisons with the oracles make thousands of calls:
one process per call cost about 0.1 s each under the sanitizers, most of their time.
"""
import json
import os
import subprocess
from collections import namedtuple
from concurrent.futures import ThreadPoolExecutor

Answer = namedtuple("Answer", "returncode stdout stderr")


def run_batch(pita, requests):
    """The answers of one `pita eval --batch -` process to `requests` (argument lists)."""
    text = "".join(json.dumps(list(args)) + "\n" for args in requests)
    r = subprocess.run([pita, "eval", "--batch", "-"], input=text, capture_output=True, text=True)
    lines = r.stdout.splitlines()
    # exit 0 or the worst request's code; 3 (or a short answer) means the batch itself failed
    if r.returncode not in (0, 2, 4) or len(lines) != len(requests):
        raise RuntimeError("pita eval --batch: exit %d, %d answers for %d requests: %s" % (
            r.returncode, len(lines), len(requests), r.stderr.strip()[:400]))
    out = []
    for line in lines:
        a = json.loads(line)
        out.append(Answer(a["exit"], a["stdout"], a["stderr"]))
    return out


def eval_many(pita, requests, workers=None):
    """The answers to `requests`, in order, from `workers` batch processes run side by side
    (default: the number of cores), each taking a few small chunks in turn."""
    requests = list(requests)
    if not requests:
        return []
    workers = workers or max(2, os.cpu_count() or 2)
    size = max(1, -(-len(requests) // (4 * workers)))
    chunks = [requests[i:i + size] for i in range(0, len(requests), size)]
    with ThreadPoolExecutor(max_workers=workers) as ex:
        answers = list(ex.map(lambda c: run_batch(pita, c), chunks))
    return [a for chunk in answers for a in chunk]
