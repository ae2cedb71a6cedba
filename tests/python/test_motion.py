"""pita.methods() and pita.motion(...): the motions of the CLI, vectorised."""
import math

import numpy as np
import pytest

import pita


def test_methods_list_the_papers_methods():
    ids = [m.id for m in pita.methods()]
    for expected in ["P1", "P2", "P3", "P4", "P5", "P6", "P7", "P8", "P9", "P10", "P5S", "SMA", "SAM"]:
        assert expected in ids
    sam = next(m for m in pita.methods() if m.id == "SAM")
    assert sam.kind == "poses" and sam.space and sam.min_count == 2
    p6 = next(m for m in pita.methods() if m.id == "P6")
    assert p6.kind == "arrows" and p6.mnemonic == "La-LP" and p6.min_count == 3


ARROW_METHODS = [m.id for m in pita.methods() if m.kind == "arrows"]


@pytest.mark.parametrize("method", ARROW_METHODS)
def test_every_arrow_method_interpolates_its_keyframes(method, figure_one):
    arrows, knots = figure_one
    count = next(m.min_count for m in pita.methods() if m.id == method)
    keys, times = (arrows, knots) if count == 3 else ([arrows[0], arrows[2]], [0, 1])
    motion = pita.motion(method, keys, times)
    for key, t in zip(keys, times):
        D = motion(t)
        assert D.p == pytest.approx(key.p, abs=1e-12)
        assert D.m == pytest.approx(key.m, rel=1e-12)
        # the segment; some methods keep the winding only modulo 2 pi (P1, P5, P7, P8: an
        # affinity has no turns; Fig. 10's "winding" column)
        turns = (D.w - key.w) / (2 * math.pi)
        assert turns == pytest.approx(round(turns), abs=1e-12)


def test_scalar_and_array_calls_agree_and_arrays_keep_their_shape(figure_one):
    arrows, knots = figure_one
    motion = pita.motion("P6", arrows, knots)
    t = np.linspace(-0.2, 1.2, 12).reshape(3, 4)
    p, m, w, q = motion(t)
    assert p.shape == (3, 4, 2) and m.shape == (3, 4) and w.shape == (3, 4) and q.shape == (3, 4, 2)
    for i in range(3):
        for j in range(4):
            D = motion(float(t[i, j]))
            assert (D.p, D.m, D.w, D.q) == (tuple(p[i, j]), m[i, j], w[i, j], tuple(q[i, j]))
    assert motion(np.array(0.5)).__class__ is pita.Arrow            # a 0-d array is a scalar
    assert motion([]).p.shape == (0, 2)
    assert motion.method == "P6" and motion.kind == "arrows" and motion.knots == (0.0, 0.5, 1.0)


def test_similarity_invariance_of_p6(figure_one):
    """PITA Fig. 10: P6 commutes with similarities (a rotation, scaling and translation of the keyframes)."""
    arrows, knots = figure_one
    s, turn, shift = 1.7, 0.9, complex(2.0, -1.0)

    def moved(a):
        z = complex(*a.p) * s * complex(math.cos(turn), math.sin(turn)) + shift
        return pita.Arrow((z.real, z.imag), a.m * s, a.w + turn)

    t = np.linspace(0, 1, 9)
    p, m, w, _ = pita.motion("P6", arrows, knots)(t)
    p2, m2, w2, _ = pita.motion("P6", [moved(a) for a in arrows], knots)(t)
    z = (p[:, 0] + 1j * p[:, 1]) * s * complex(math.cos(turn), math.sin(turn)) + shift
    np.testing.assert_allclose(p2[:, 0] + 1j * p2[:, 1], z, atol=1e-12)
    np.testing.assert_allclose(m2, m * s, rtol=1e-12)
    np.testing.assert_allclose(w2, w + turn, atol=1e-12)


def test_options_and_chains_are_those_of_a_scene(figure_one):
    arrows, knots = figure_one
    start = pita.motion("P2", arrows, knots)(0.25)
    mid = pita.motion("P2", arrows, knots, anchor="midpoint")(0.25)
    assert start != mid
    also_mid = pita.motion("P2", arrows, knots, options={"anchor": "midpoint"})(0.25)
    assert also_mid == mid
    track = pita.motion("P6", arrows + [pita.Arrow((8, 1), 1, 5)], knots + [1.5], chain="neville")
    assert track.chain == "neville" and track(1.5).p == pytest.approx((8.0, 1.0))
    dicts = [{"t": t, "p": list(a.p), "m": a.m, "w": a.w} for a, t in zip(arrows, knots)]
    assert pita.motion("P6", dicts)(0.3) == pita.motion("P6", arrows, knots)(0.3)


def test_errors_name_the_pointer(figure_one):
    arrows, knots = figure_one
    bad = [{"p": [0, 0], "m": 1, "w": 0}, {"p": [1, 0], "m": -2, "w": 0}, {"p": [2, 0], "m": 1, "w": 0}]
    with pytest.raises(pita.SceneError) as caught:
        pita.motion("P6", bad, [0, 1, 2])
    error = caught.value
    assert error.pointer == "/keyframes/1/m" and error.file == "<pita.motion>"
    assert "magnitude must be > 0" in error.reason and isinstance(error, ValueError)
    with pytest.raises(pita.SceneError) as caught:
        pita.motion("P66", arrows, knots)
    assert caught.value.pointer == "/method"
    with pytest.raises(pita.SceneError) as caught:
        pita.motion("P6", arrows, [0, 1, 0.5])
    assert caught.value.pointer == "/keyframes/2/t"
    with pytest.raises(pita.SceneError) as caught:
        pita.motion("P6", arrows, knots, anchr="midpoint")
    assert caught.value.pointer == "/anchr"
    assert 'did you mean "anchor"?' in caught.value.reason
    with pytest.raises(ValueError):
        pita.motion("P6", arrows, [0, 1])
    with pytest.raises(ValueError):
        pita.motion("P6", arrows)


OPTIONS = ["anchor", "path_mean", "magnitude_mean", "knots", "permutation", "symmetrize"]


@pytest.mark.parametrize("keyword, meant", [("anchr", "anchor"), ("pathmean", "path_mean"),
                                            ("magnitude_means", "magnitude_mean"), ("permutaton", "permutation"),
                                            ("symetrize", "symmetrize"), ("chian", "chain"), ("timings", "timing"),
                                            ("option", "options")])
def test_a_misspelt_keyword_gets_a_did_you_mean_among_the_option_names(keyword, meant, figure_one):
    arrows, knots = figure_one
    with pytest.raises(pita.SceneError) as caught:
        pita.motion("P2", arrows, knots, **{keyword: "midpoint"})
    reason = caught.value.reason
    assert f'unknown keyword "{keyword}"; did you mean "{meant}"?' in reason
    assert caught.value.pointer == f"/{keyword}" and caught.value.file == "<pita.motion>"
    # the names it takes, not the scene file's top-level fields
    assert ", ".join(OPTIONS) in reason and "the scene fields chain, timing" in reason
    for field in ["canvas", "layers", "golden", "claims", "title"]:
        assert field not in reason


def test_the_scene_fields_are_those_of_the_kind_of_motion(figure_one):
    arrows, knots = figure_one
    poses = [np.eye(2, 3), [[0, -2, 3], [2, 0, 1]]]
    with pytest.raises(pita.SceneError) as caught:
        pita.motion("SAM", poses, [0, 1], chain="blend")
    assert "timing, subdivisions of a motion of poses" in caught.value.reason
    with pytest.raises(pita.SceneError) as caught:
        pita.motion("SAM", poses, [0, 1], subdivision=2)
    assert 'did you mean "subdivisions"?' in caught.value.reason
    with pytest.raises(pita.SceneError) as caught:
        pita.motion("P6", arrows, knots, subdivisions=2)
    assert "chain, timing of a motion of keyframes" in caught.value.reason
    pita.motion("SAM", poses, [0, 1], subdivisions=2)
    pita.motion("P6", arrows, knots, timing={"ease": "linear"})


def test_a_keyword_far_from_every_name_lists_them(figure_one):
    arrows, knots = figure_one
    for keyword in ["title", "canvas", "samples", "zzz"]:   # a figure's fields are load_scene's, not motion's
        with pytest.raises(pita.SceneError) as caught:
            pita.motion("P6", arrows, knots, **{keyword: 1})
        assert "did you mean" not in caught.value.reason and ", ".join(OPTIONS) in caught.value.reason


def test_an_option_the_method_does_not_read_is_refused(figure_one):
    """As in a scene file's "options": P6 reads no anchor, so anchor= would change nothing."""
    arrows, knots = figure_one
    for given in [dict(anchor="midpoint"), dict(options={"anchor": "midpoint"})]:
        with pytest.raises(ValueError) as caught:
            pita.motion("P6", arrows, knots, **given)
        assert isinstance(caught.value, pita.SceneError)
        assert '"anchor"' in caught.value.reason and "P2" in caught.value.reason
        assert caught.value.pointer == "/options/anchor"
    with pytest.raises(pita.SceneError) as caught:
        pita.motion("P6", arrows, knots, path_mean="arithmetic")
    assert "SMA" in caught.value.reason and "P9" in caught.value.reason
    pita.motion("P2", arrows, knots, anchor="midpoint")                 # P2 reads it
    pita.motion("P9", arrows, knots, path_mean="arithmetic")            # P9 reads it


def test_no_sam_is_a_no_motion_error():
    with pytest.raises(pita.NoMotionError) as caught:
        pita.motion("SAM", [np.eye(2, 3), [[-1, 0, 0], [0, -2, 0]]], [0, 1])
    assert "no SAM" in str(caught.value) and caught.value.pointer.startswith("/poses")


def test_keyframes_may_be_an_array():
    poses = np.stack([np.eye(2, 3), [[0, -2, 3], [2, 0, 1]]])          # each item a new view
    np.testing.assert_array_equal(pita.motion("SAM", poses, [0, 1])(np.linspace(0, 1, 3)),
                                  pita.motion("SAM", list(poses), [0, 1])(np.linspace(0, 1, 3)))


def test_pose_motions_of_the_plane_and_of_space():
    A = pita.Pose(np.eye(2), [0, 0])
    B = pita.Pose([[0, -2], [2, 0]], [3, 1])
    motion = pita.motion("SAM", [A, B], [0, 1])
    assert motion.kind == "poses"
    frames = motion(np.linspace(0, 1, 5))
    assert frames.shape == (5, 2, 3)
    np.testing.assert_allclose(frames, pita.sam(A, B, np.linspace(0, 1, 5)), atol=1e-14)
    assert motion(1.0) == B or np.allclose(motion(1.0).matrix, B.matrix, atol=1e-14)
    space = pita.motion("SAM", [np.eye(3, 4), np.diag([2.0, 2.0, 2.0, 1.0])], [0, 1])
    assert space.kind == "poses3d" and space(np.zeros(3)).shape == (3, 3, 4)
    linear = pita.motion("linear", [A, B], [0, 1])
    np.testing.assert_allclose(linear(0.5), (A.matrix + B.matrix) / 2, atol=1e-15)


def _similarity(p, m, w):
    c, s = m * math.cos(w), m * math.sin(w)
    return np.array([[c, -s, p[0]], [s, c, p[1]]])


@pytest.mark.parametrize("method", ["P4", "P5", "P6", "P9"])
def test_pose_pitas_take_poses_in_the_plane_and_in_space(method):
    # Given as poses, a PITA's name is the pose PITA: through the poses, and on
    # similarities the arrow PITA of the same name given the matching arrows.
    arrows = [pita.Arrow((0, 0), 1, 0.3), pita.Arrow((3, 1.5), 0.6, 2.0), pita.Arrow((6, 0), 1.2, 3.5)]
    knots = [0, 0.4, 1]
    poses = [pita.Pose.from_matrix(_similarity(a.p, a.m, a.w)) for a in arrows]
    motion = pita.motion(method, poses, knots)
    assert motion.kind == "poses"
    times = np.linspace(-0.2, 1.2, 15)
    frames = motion(times)
    assert frames.shape == (15, 2, 3)
    expected = [pita.motion(method, arrows, knots)(t) for t in times]
    np.testing.assert_allclose(frames, [_similarity(D.p, D.m, D.w) for D in expected], atol=1e-12)
    for pose, t in zip(poses, knots):
        np.testing.assert_array_equal(motion(t), pose.matrix)
    sheared = [np.eye(3, 4), [[1, 0.5, 0, 1], [0, 1, 0, 0], [0, 0.3, 1.2, 2]], [[0, -1, 0, 2], [1, 0, 0, 1], [0, 0, 1, 0]]]
    space = pita.motion(method, sheared, [0, 1, 2])
    assert space.kind == "poses3d"
    np.testing.assert_array_equal(space(np.array([0.0, 1.0, 2.0])), np.array(sheared, dtype=float))


def test_a_pose_pita_without_a_real_power_is_refused():
    flipped = [np.eye(2, 3), [[-1, 0.2, 3], [0, -1, 1]], [[1, 0, 5], [0, 1, 3]]]
    with pytest.raises(ValueError, match="no SAM exists between these poses"):
        pita.motion("P6", flipped, [0, 1, 2])
