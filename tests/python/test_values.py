"""pita.Arrow and pita.Pose: plain values that compare, hash, print and pickle."""
import math
import pickle
import struct

import numpy as np
import pytest

import pita


def test_arrow_fields_and_end_point():
    a = pita.Arrow((1, 2), 2.0, math.pi / 2)
    assert a.p == (1.0, 2.0) and a.m == 2.0 and a.w == math.pi / 2
    assert a.q == pytest.approx((1.0, 4.0))
    assert pita.Arrow((0, 0), 1, 0.3 + 2 * math.pi).turns == 1


def test_arrow_equality_hash_repr_and_pickle():
    a = pita.Arrow([0, 0], 1, 0.4)
    b = pita.Arrow(np.array([0.0, 0.0]), 1.0, 0.4)
    assert a == b and hash(a) == hash(b)
    assert a != pita.Arrow((0, 0), 1, 0.4 + 2 * math.pi)  # one more turn: another arrow
    assert repr(a) == "Arrow(p=(0.0, 0.0), m=1.0, w=0.4)"
    assert eval(repr(a), {"Arrow": pita.Arrow}) == a
    assert pickle.loads(pickle.dumps(a)) == a
    assert (a == "an arrow") is False


def test_arrow_from_points_is_the_zero_turn_arrow():
    a = pita.Arrow.from_points((0, 0), (0, 2))
    assert a.m == 2.0 and a.w == pytest.approx(math.pi / 2) and a.turns == 0


@pytest.mark.parametrize("p, m, w, error", [
    ((0, 0), 0.0, 0.0, ValueError),          # magnitude must be > 0
    ((0, 0), -1.0, 0.0, ValueError),
    ((0, 0), float("nan"), 0.0, ValueError),
    ((0, 0), 1.0, float("inf"), ValueError),
    ((0, 0, 0), 1.0, 0.0, ValueError),       # not a point
    ("xy", 1.0, 0.0, ValueError),
    ((0, 0), "1", 0.0, TypeError),
    ((0, 0), True, 0.0, TypeError),
])
def test_bad_arrows_are_refused(p, m, w, error):
    with pytest.raises(error):
        pita.Arrow(p, m, w)


def test_numbers_beyond_a_double_and_windings_beyond_the_bound_name_their_argument():
    with pytest.raises(ValueError, match=r"^m: an integer of 1329 bits, beyond the range of a double"):
        pita.Arrow((0, 0), 10**400, 0)
    with pytest.raises(ValueError, match=r"^w: the winding must be within \+-1e\+06 rad"):
        pita.Arrow((0, 0), 1, 1e300)  # its turns overflowed a 64-bit integer
    assert pita.Arrow((0, 0), 1, 1e6).turns == round(1e6 / (2 * math.pi))


def test_a_damaged_pickle_is_refused_as_the_constructor_refuses():
    good = pickle.dumps(pita.Arrow((1, 2), 3.0, 0.5))
    for bad_m in (-1.0, 0.0, float("nan")):
        # The float opcode "G" and its 8 bytes, big-endian: m = 3.0 made bad.
        damaged = good.replace(b"G" + struct.pack(">d", 3.0), b"G" + struct.pack(">d", bad_m))
        assert damaged != good
        with pytest.raises(ValueError, match=r"^m: (magnitude must be > 0|must be finite)"):
            pickle.loads(damaged)


def test_pose_of_the_plane_and_its_forms():
    P = pita.Pose([[0, -1], [1, 0]], [2, 0])
    assert P.dimension == 2
    np.testing.assert_array_equal(P.matrix, [[0, -1, 2], [1, 0, 0]])
    np.testing.assert_array_equal(P.homogeneous, [[0, -1, 2], [1, 0, 0], [0, 0, 1]])
    np.testing.assert_array_equal(np.asarray(P), P.matrix)
    assert pita.Pose.from_matrix(P.homogeneous) == P
    assert pita.Pose.from_matrix(P.matrix) == P
    assert repr(P) == "Pose(L=[[0.0, -1.0], [1.0, 0.0]], b=[2.0, 0.0])"
    assert pickle.loads(pickle.dumps(P)) == P and hash(P) == hash(pita.Pose.from_matrix(P.matrix))


def test_pose_compose_and_inverse():
    A = pita.Pose([[2, 0], [0, 1]], [1, 1])
    B = pita.Pose([[0, -1], [1, 0]], [0, 3])
    np.testing.assert_allclose((A @ B).homogeneous, A.homogeneous @ B.homogeneous)
    np.testing.assert_allclose((A @ A.inverse()).homogeneous, np.eye(3), atol=1e-15)


def test_pose_of_space():
    P = pita.Pose(np.eye(3) * 2, [1, 2, 3])
    assert P.dimension == 3 and P.matrix.shape == (3, 4)
    assert pita.Pose.from_matrix(P.homogeneous) == P


@pytest.mark.parametrize("matrix", [
    np.zeros((2, 2)), np.zeros((4, 3)), [[1, 0, 0], [0, 1, 0], [1, 0, 1]],  # bad last row
    [[1, 0, float("nan")], [0, 1, 0]],
])
def test_bad_poses_are_refused(matrix):
    with pytest.raises(ValueError):
        pita.Pose.from_matrix(matrix)
