"""pita.sma, ear_power, sam and has_sam, checked against their defining properties and
against SciPy's general matrix functions (an independent implementation)."""
import math

import numpy as np
import pytest
import scipy.linalg

import pita

RNG = np.random.default_rng(20261206)


def homogeneous(M):
    M = np.asarray(M, dtype=float)
    n = M.shape[-1] - 1
    if M.shape[-2] == n + 1:
        return M
    H = np.zeros(M.shape[:-2] + (n + 1, n + 1))
    H[..., :n, :] = M
    H[..., n, n] = 1.0
    return H


def positive_affinity(n):
    """A random affinity whose linear part is near a rotation and scaling: it has real powers."""
    while True:
        L = np.eye(n) + 0.4 * RNG.standard_normal((n, n))
        if np.all(np.linalg.eigvals(L).real > 0.1) and np.linalg.det(L) > 0.1:
            return np.hstack([L, RNG.standard_normal((n, 1))])


@pytest.mark.parametrize("n", [2, 3])
def test_ear_power_agrees_with_scipy(n):
    for _ in range(50):
        M = positive_affinity(n)
        for t in (0.5, -1.3, 2.7):
            ours = pita.ear_power(M, t)
            theirs = np.real(scipy.linalg.fractional_matrix_power(homogeneous(M), t))[:n]
            np.testing.assert_allclose(ours, theirs, rtol=1e-9, atol=1e-9)


@pytest.mark.parametrize("n", [2, 3])
def test_ear_power_group_laws(n):
    M = positive_affinity(n)
    H = homogeneous(M)
    np.testing.assert_allclose(pita.ear_power(H, 0.0), np.eye(n + 1), atol=1e-14)
    np.testing.assert_allclose(pita.ear_power(H, 1.0), H, atol=1e-13)
    half = pita.ear_power(H, 0.5)
    np.testing.assert_allclose(half @ half, H, atol=1e-12)
    np.testing.assert_allclose(pita.ear_power(H, 0.3) @ pita.ear_power(H, 0.9), pita.ear_power(H, 1.2), atol=1e-12)


def test_square_root_of_a_quarter_turn():
    root = pita.ear_power([[0, -1, 2], [1, 0, 0]], 0.5)
    c = math.sqrt(0.5)
    np.testing.assert_allclose(root[:, :2], [[c, -c], [c, c]], atol=1e-15)


def test_ear_power_broadcasts_as_numpy_does():
    Ms = np.stack([positive_affinity(2) for _ in range(4)])           # (4, 2, 3)
    t = np.linspace(0, 1, 5)
    assert pita.ear_power(Ms[0], t).shape == (5, 2, 3)
    assert pita.ear_power(Ms, 0.5).shape == (4, 2, 3)
    out = pita.ear_power(Ms[:, None], t[None, :])                        # (4, 1) with (1, 5)
    assert out.shape == (4, 5, 2, 3)
    for i in range(4):
        for j in range(5):
            np.testing.assert_array_equal(out[i, j], pita.ear_power(Ms[i], t[j]))
    with pytest.raises(ValueError):
        pita.ear_power(Ms, np.zeros(3))                                  # 4 and 3 do not broadcast
    assert pita.ear_power(homogeneous(Ms), t[:4]).shape == (4, 3, 3)     # homogeneous in, homogeneous out


def test_dtypes():
    M = [[2, 0, 1], [0, 3, 0]]                                           # integers are converted
    assert pita.ear_power(M, 1).dtype == np.float64
    np.testing.assert_allclose(pita.ear_power(np.array(M, dtype=np.float32), 1), M)
    assert pita.ear_power(M, np.arange(3, dtype=np.int8)).shape == (3, 2, 3)
    with pytest.raises(TypeError):
        pita.ear_power(M, np.array([0.5j]))
    with pytest.raises(TypeError):
        pita.ear_power(M, ["a"])
    with pytest.raises(TypeError):
        pita.ear_power(np.array(M, dtype=complex), 0.5)
    with pytest.raises(ValueError):
        pita.ear_power(M, float("nan"))


def test_no_real_power_raises_with_the_index():
    good = positive_affinity(2)
    bad = np.array([[-1.0, 0.0, 0.0], [0.0, -2.0, 0.0]])                 # two negative eigenvalues: G3
    with pytest.raises(pita.NoSamError) as caught:
        pita.ear_power(np.stack([good, good, bad]), 0.5)
    assert caught.value.index == 2 and "eigenvalue" in caught.value.reason
    with pytest.raises(pita.NoSamError) as caught:
        pita.ear_power(bad, 0.5)
    assert caught.value.index is None
    assert isinstance(caught.value, ValueError) and isinstance(caught.value, pita.Error)


def test_has_sam_and_its_cases():
    assert pita.has_sam([[0, -1, 0], [1, 0, 0]]).case == "G1"            # a quarter turn
    assert pita.has_sam([[2, 0, 0], [0, 3, 0]]).case == "G2"
    assert pita.has_sam([[1, 1, 0], [0, 1, 0]]).case == "S1"             # a shear
    assert pita.has_sam([[-2, 0, 0], [0, -2, 0]]).case == "S2"           # a half turn, scaled
    no = pita.has_sam([[-1, 0, 0], [0, -2, 0]])
    assert not no and no.case == "G3" and no.reason
    assert not pita.has_sam([[1, 0, 0], [0, -1, 0]])                     # a mirror
    assert pita.has_sam(np.diag([2.0, 3.0, 4.0, 1.0]))
    assert not pita.has_sam(np.diag([-1.0, -2.0, 3.0, 1.0]))
    A = pita.Pose(np.eye(2), [0, 0])
    assert pita.has_sam(A, pita.Pose([[0, -1], [1, 0]], [1, 1]))


def test_sma_interpolates_and_agrees_with_the_motion(figure_one):
    (A, _, B), _ = figure_one
    assert pita.sma(A, B, 0.0) == A and pita.sma(A, B, 1.0) == B
    t = np.linspace(-0.5, 1.5, 41)
    p, m, w, q = pita.sma(A, B, t)
    # the SMA method of a scene evaluates from A at every t; pita.sma from the nearer end
    # (core/steady_morph.hpp), so that sma(A, B, 1) is B exactly: they agree to rounding
    p2, m2, w2, q2 = pita.motion("SMA", [A, B], [0, 1])(t)
    np.testing.assert_allclose(p, p2, rtol=0, atol=1e-13)
    np.testing.assert_allclose(w, w2, rtol=0, atol=1e-13)
    # steady: consecutive frames differ by the same similarity, so m grows geometrically and w linearly
    np.testing.assert_allclose(np.diff(np.log(m)), np.diff(np.log(m))[0], atol=1e-12)
    np.testing.assert_allclose(np.diff(w), (B.w - A.w) / 20, atol=1e-12)


@pytest.mark.parametrize("n", [2, 3])
def test_sam_is_the_power_of_the_relative_affinity(n):
    A, B = positive_affinity(n), positive_affinity(n)
    HA, HB = homogeneous(A), homogeneous(B)
    if not pita.has_sam(HB @ np.linalg.inv(HA)):
        pytest.skip("no SAM between this random pair")
    t = np.linspace(0, 1, 7)
    S = pita.sam(A, B, t)
    assert S.shape == (7, n, n + 1)
    np.testing.assert_allclose(S[0], A, atol=1e-13)
    np.testing.assert_allclose(S[-1], B, atol=1e-12)
    for k, tk in enumerate(t):
        expected = scipy.linalg.fractional_matrix_power(HB @ np.linalg.inv(HA), tk).real @ HA
        np.testing.assert_allclose(S[k], expected[:n], atol=1e-9)


def test_sam_refuses_when_there_is_none():
    with pytest.raises(pita.NoSamError):
        pita.sam(np.eye(2, 3), [[-1, 0, 0], [0, -2, 0]], 0.5)


@pytest.mark.parametrize("n", [2, 3])
def test_one_matrix_gives_what_a_batch_gives_bitwise(n):
    """A single matrix at a number t (the call of a Python loop) takes a path of its own,
    without NumPy's conversions: its results are those of the same matrix in a batch, to the bit,
    whatever form it is given in."""
    stack = np.stack([positive_affinity(n) for _ in range(40)])
    for t in (0.5, -1.3, 2, 0):
        batch = pita.ear_power(stack, t)
        hbatch = pita.ear_power(homogeneous(stack), t)
        for k, M in enumerate(stack):
            for given in (M, M.tolist(), tuple(map(tuple, M.tolist())), np.asfortranarray(M), pita.Pose.from_matrix(M)):
                one = pita.ear_power(given, t)
                assert one.shape == (n, n + 1) and one.dtype == np.float64
                np.testing.assert_array_equal(one, batch[k])
            single = M.astype(np.float32)
            np.testing.assert_array_equal(pita.ear_power(single, t), pita.ear_power(single[None], t)[0])
            H = homogeneous(M)
            np.testing.assert_array_equal(pita.ear_power(H, t), hbatch[k])
            np.testing.assert_array_equal(pita.ear_power(H.tolist(), t), hbatch[k])
    ints = [[2, 0, 1], [0, 3, 0]]
    np.testing.assert_array_equal(pita.ear_power(ints, 0.5), pita.ear_power(np.array([ints]), 0.5)[0])
    np.testing.assert_array_equal(pita.ear_power(np.array(ints), 0.5), pita.ear_power(np.array([ints]), 0.5)[0])
    np.testing.assert_array_equal(pita.ear_power([[2.0, 0, 1], [0, 3, np.float64(0)]], np.float64(0.5)),
                                  pita.ear_power(np.array([ints]), 0.5)[0])


def test_one_matrix_is_refused_as_a_batch_is():
    """What the small path does not take goes the general way, with its errors."""
    for bad, error in [([[1, 0, float("nan")], [0, 1, 0]], ValueError),
                       ([[1, 0, 0], [0, 1, 0], [0, 1, 1]], ValueError),          # not [0, 0, 1]
                       ([[1, 0, 0], [0, 1]], ValueError),                        # ragged
                       ([[True, False, False], [False, True, False]], TypeError),
                       ([[1, 0], [0, 1]], ValueError),                           # 2x2: no translation
                       ([["1", 0, 0], [0, 1, 0]], TypeError)]:
        with pytest.raises(error) as one:
            pita.ear_power(bad, 0.5)
        assert not isinstance(one.value, pita.NoSamError)
    with pytest.raises(pita.NoSamError) as caught:
        pita.ear_power([[-1, 0, 0], [0, -2, 0]], 0.5)
    assert caught.value.index is None and "eigenvalue" in caught.value.reason
    with pytest.raises(TypeError):
        pita.ear_power([[1, 0, 2**70], [0, 1, 0]], 0.5)                       # NumPy's dtype object
