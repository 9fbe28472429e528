"""Issue 29's soak, short (the long one: `make soak`, tests/bench/soak.py). Cura's libArcus 4.13 reads each
frame's three header integers with single 4-byte recv() calls and loses the frame, and the framing after
it, when one returns fewer bytes; a Cura user got G-code missing a layer. Here, on the real libArcus
(tests/bench/soak_receiver.py, Debian's python3-arcus, a new socket per slice as Cura makes it):

- slices of small models in every dialect case of test_connect.py and a two-model case, object names of
  1..80 characters (46 among them: the reproduction), each byte-identical with the command line's G-code
  and with no libArcus error;
- early closes at random moments (seeded; the seed is printed, MIXENGINE_SOAK_SEED=n repeats a run, with
  the 'during' delays scaled by this machine's slicing time): Cura closing its socket (a setting changed),
  SIGTERM (CuraEngineBackend._terminate) or Cura vanishing, before a slice, right after sending it, during
  it (at a random time, or after a random number of layers arrived) and after it: the engine exits 0,
  never by a signal, never hangs;
- on a model with many layers, G-code layers reach Cura while the slice runs: at least one ;LAYER: chunk
  arrives before the last Progress message (order of arrival, no timing thresholds).

About 1.5 minutes on 2 cores."""
import os
import random
import sys

import pytest

import helpers

sys.path.insert(0, str(helpers.REPO / "tests" / "bench"))
import soak  # noqa: E402

SEED = int(os.environ.get("MIXENGINE_SOAK_SEED", random.SystemRandom().randrange(1 << 31)))
BOXES = ("box20x20x10", "box10x10x3", "box15x15x40")
HANG_S = 20


@pytest.fixture(scope="module")
def setup(engine, tmp_path_factory):
    folder = tmp_path_factory.mktemp("soak")
    paths = {name: soak.box_stl(folder / f"{name}.stl", *soak.BOXES[name]) for name in BOXES}
    cases = {c: soak.case_settings(c) for c in soak.CASES}
    return folder, paths, cases


def describe(results):
    def what(r):
        if r["kind"] == "slice":
            return f"{r['case']} {r['model']} name of {r['name_chars']} characters"
        return f"{r['how']} {r['moment']} at {r.get('acted_at', 0):.2f} s, {r['case']} {r['model']}"
    return "\n".join(f"  {r['id']} {what(r)}: " + "; ".join(r["problems"])
                     + (f" [libArcus: {r['error_counts']}]" if r.get("error_counts") else "")
                     + (f" [stderr: {r['stderr'].strip().splitlines()[-1][:200]}]"
                        if r.get("stderr", "").strip() else "")
                     + "".join(f"\n      {line}" for line in soak.stack_digest(r.get("hang_stacks")))
                     for r in results)


def test_slices_are_byte_identical_with_the_command_line_and_libarcus_has_no_error(engine, setup, report):
    folder, paths, cases = setup
    rng = random.Random(SEED)
    jobs = []
    for case in soak.CASES:
        for model in BOXES:
            for k in range(3):  # a name of 46 characters once per case and model, the others 1..80
                length = soak.REPRO_NAME_LEN if k == 0 else rng.randint(1, 80)
                name = "n" * length if k == 0 else soak.object_name(rng, length)
                jobs.append(soak.slice_job(f"s{len(jobs):03d}", case, model, paths[model], name))
    for k in range(4):  # issue 29's reproduction: lost layer 23 in 5 of 6 tries with names of 46 characters
        name = soak.object_name(rng, soak.REPRO_NAME_LEN, ascii_only=True)
        jobs.append(soak.slice_job(f"s{len(jobs):03d}", soak.REPRO_CASE, soak.REPRO_MODEL,
                                   paths[soak.REPRO_MODEL], name))
    assert len(jobs) >= 50
    refs = soak.references(engine, {(j["case"], j["model"]) for j in jobs}, paths, folder / "reference")
    results = soak.run_receivers(engine, cases, jobs, folder / "run", progress_every=None)
    texts = {key: path.read_text() for key, path in refs.items()}
    for job, r in zip(jobs, results):
        r.update(model=job["model"], name_chars=len(job["name"]))
        soak.check_slice(r, job, texts[(job["case"], job["model"])])
    bad = [r for r in results if not r["ok"]]
    errors = sum(r.get("error_count", 0) for r in results)
    report(f"soak (seed {SEED}): {len(results) - len(bad)}/{len(results)} slices byte-identical, "
           f"{errors} libArcus errors")
    assert not bad, f"seed {SEED}: {len(bad)} of {len(results)} slices failed:\n{describe(bad)}"


def test_early_closes_at_random_moments_end_the_engine_with_exit_0(engine, setup, report):
    """The contract: when Cura ends the talk (closes its socket before, during or after a slice, sends
    SIGTERM, or goes away) the engine exits 0, promptly; never a crash signal, never a hang."""
    folder, paths, cases = setup
    rng = random.Random(SEED + 1)
    one_model_cases = [c for c in soak.CASES if soak.CASES[c][2] == "one"]
    early_models = ("box20x20x10", "box15x15x40")
    timings = {m: soak.slice_timing(engine, paths[m], folder) for m in early_models}
    jobs = []
    for i in range(120):  # 8 of each (how, moment)
        how, moment = soak.HOWS[i % len(soak.HOWS)], soak.MOMENTS[(i // len(soak.HOWS)) % len(soak.MOMENTS)]
        model = rng.choice(early_models)
        jobs.append(soak.early_job(f"e{i:03d}", rng.choice(one_model_cases), model, paths[model], how, moment,
                                   hang_s=HANG_S, **soak.moment_of(rng, moment, timings[model])))
    rng.shuffle(jobs)
    # a broken engine stops the run after a few failures instead of spending HANG_S on each
    results = soak.run_receivers(engine, {c: cases[c] for c in one_model_cases}, jobs, folder / "early",
                                 stop_after_failures=4, progress_every=None)
    for job, r in zip(jobs, results):
        soak.check_early(r, job)
    ran = [r for r in results if not r.get("skipped")]
    bad = [r for r in ran if not r["ok"]]
    report(f"soak (seed {SEED + 1}): {len(ran) - len(bad)}/{len(ran)} early closes ended with exit 0"
           + (f" ({len(results) - len(ran)} not run after the failures)" if len(ran) < len(results) else ""))
    for line in soak.early_table(ran):
        report("  " + line)
    assert not bad, (f"seed {SEED + 1}: {len(bad)} early closes failed (the run stops after 4, "
                     f"{len(results) - len(ran)} not run):\n{describe(bad)}")
    assert len(ran) == len(results) >= 100


def test_layers_reach_cura_while_the_slice_runs(engine, setup, corpus, tmp_path, report):
    """Order of arrival only: some ;LAYER: chunk (not just the start chunk) before the last Progress."""
    _, _, cases = setup
    model = corpus("armadillo52k")
    ref = soak.cli_reference(engine, "ender3", model, tmp_path / "ref.gcode")
    job = soak.slice_job("order", "ender3", "armadillo52k", model, "armadillo52k.stl", arrivals=True)
    [r] = soak.run_receivers(engine, {"ender3": cases["ender3"]}, [job], tmp_path / "run", receivers=1,
                             progress_every=None)
    soak.check_slice(r, job, ref.read_text())
    assert r["ok"], "; ".join(r["problems"])
    kinds = [kind for kind, _ in r["arrivals"]]
    last_progress = max(i for i, kind in enumerate(kinds) if kind == "Progress")
    before = [i for i, kind in enumerate(kinds[:last_progress]) if kind == "GCodeLayer:LAYER"]
    times = r["times"]
    report(f"armadillo52k over the socket: {len(r['layer_chunks'])} layer chunks, {len(before)} of them before the "
           f"last Progress; first at {times['first_layer_chunk']:.2f} s, SlicingFinished at {times['finished']:.2f} s")
    assert before, (f"all {len(r['layer_chunks'])} layer chunks arrived after the last Progress message "
                    f"(first layer chunk at {times['first_layer_chunk']} s, finished at {times['finished']} s)")
