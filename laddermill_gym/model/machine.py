"""What on a machine moves a result's last bits: the kernels numpy and OpenBLAS choose at run time.

Identical seeds give identical bits in every process of one machine. Between machines they can differ, and a
knife-edge episode (turbulence that a controller survives by a hair) can end differently. Measured on 2026-12-02
(``python -m laddermill_gym.studies.numerics.machine_bits``; ``docs/numerics.md``, "Bits and machines"), the code
numba generates is not what differs: compiled for AVX2 or for AVX-512 the simulator gives the same bits. Two
libraries pick their kernels by the CPU when they load, and do move them:

* numpy's SIMD loops (:func:`numpy_simd_level`: ``X86_V3`` is AVX2, ``AVX512_ICL`` AVX-512), used where the
  turbulence's spectra and coherence are computed (``np.exp``, powers);
* OpenBLAS's kernels (:func:`blas_kernels`: ``Haswell``, ``SkylakeX``, ...), under scipy's LAPACK in the LQR
  design and in the W-methods' tableau (``kernels/rigid/rosenbrock.py``).

Both read the environment once, at load (:data:`KERNEL_VARIABLES`): ``NPY_DISABLE_CPU_FEATURES`` switches numpy's
targets off by name, ``OPENBLAS_CORETYPE`` names OpenBLAS's kernels, so one machine with AVX-512 can compute as
another would (:data:`KERNEL_ENV`).
"""

from __future__ import annotations

__all__ = ["ABOVE_AVX2", "KERNEL_VARIABLES", "KERNEL_ENV", "SAME_KERNELS", "numpy_simd_level", "blas_kernels",
           "kernel_profile"]

#: the environment variables that change which kernels numpy and OpenBLAS run on the same CPU
KERNEL_VARIABLES = ("NPY_DISABLE_CPU_FEATURES", "NPY_ENABLE_CPU_FEATURES", "OPENBLAS_CORETYPE")
#: OpenBLAS kernel names that compute as another's: its Zen target builds on the Haswell kernels, Cooperlake on
#: SkylakeX's (the LQR's gusts-v1 NTM_IB seed-0 episode gave the same bits with either name of each pair, 2026-12-02)
SAME_KERNELS = {"Zen": "Haswell", "Cooperlake": "SkylakeX"}
#: numpy's dispatch targets above AVX2 (``NPY_DISABLE_CPU_FEATURES`` with these runs its AVX2 loops)
ABOVE_AVX2 = "X86_V4 AVX512_ICL AVX512_SPR"
#: the environment that selects a profile's kernels (numpy level, OpenBLAS kernels) on a machine with AVX-512: numpy's
#: targets above AVX2 switched off (or none: an empty value), OpenBLAS's kernels named
KERNEL_ENV = {("X86_V3", "Haswell"): {"NPY_DISABLE_CPU_FEATURES": ABOVE_AVX2,
                                      "OPENBLAS_CORETYPE": "Haswell"},
              ("AVX512_ICL", "Haswell"): {"NPY_DISABLE_CPU_FEATURES": "", "OPENBLAS_CORETYPE": "Haswell"},
              ("AVX512_ICL", "SkylakeX"): {"NPY_DISABLE_CPU_FEATURES": "", "OPENBLAS_CORETYPE": "SkylakeX"}}


def numpy_simd_level() -> str:
    """numpy's highest SIMD dispatch target in this process (its build's targets the CPU has and the environment
    leaves on), e.g. ``X86_V3`` (AVX2) or ``AVX512_ICL``; ``baseline`` where numpy dispatches nothing."""
    try:
        from numpy._core._multiarray_umath import __cpu_dispatch__, __cpu_features__
    except ImportError:  # numpy 1.x's layout
        from numpy.core._multiarray_umath import __cpu_dispatch__, __cpu_features__
    on = [t for t in __cpu_dispatch__ if __cpu_features__.get(t)]
    return on[-1] if on else "baseline"


def blas_kernels() -> str:
    """The kernels of the OpenBLAS under scipy's LAPACK (threadpoolctl's ``architecture``), as :data:`SAME_KERNELS`
    names them; ``none`` when scipy's BLAS is not an OpenBLAS."""
    import scipy.linalg  # noqa: F401  (loads scipy's BLAS, so that threadpoolctl sees it)
    from threadpoolctl import threadpool_info

    names = [d.get("architecture") for d in threadpool_info() if d.get("internal_api") == "openblas"]
    name = next((n for n in names if n), "none")
    return SAME_KERNELS.get(name, name)


def kernel_profile() -> tuple[str, str]:
    """(numpy's SIMD level, OpenBLAS's kernels) of this process: what, beside the code and the seed, fixes a
    result's bits."""
    return numpy_simd_level(), blas_kernels()
