# Compiler settings every revsph target gets through the `revsph_flags` interface target.
#
# Bitwise reproducibility (design note exact-reversibility.md §6): no FMA contraction, no
# fast-math reassociation, round-to-nearest IEEE arithmetic. tests/fma_contraction_test.cpp checks
# that the flags reach the physics code.
#
# -fno-math-errno only stops sqrt and llrint from setting errno: GCC then emits the single
# instructions (sqrtsd, cvtsd2si) instead of library calls, with identical, correctly rounded
# results (llrint rounds in the current mode either way; range checks come before it).
add_library(revsph_flags INTERFACE)
target_compile_options(revsph_flags INTERFACE
  -ffp-contract=off
  -fno-fast-math
  -fno-associative-math
  -fno-reciprocal-math
  -fno-math-errno
  -Wall -Wextra -Wpedantic -Wshadow
  # State fields are declared with designated initialisers that leave out the members with
  # defaults (core/particle_sets.hpp); GCC 12 warns about each omission, GCC 13 no longer does.
  -Wno-missing-field-initializers)
# No FMA instructions at all on x86-64: GCC 12's SLP vectorizer fuses a multiply with an
# alternating subtract/add (vfmsubadd) despite -ffp-contract=off when the target has FMA
# (-march=native), which changed shtc's 3D kernel sums. Compilers for other CPUs lack the flag.
include(CheckCXXCompilerFlag)
check_cxx_compiler_flag(-mno-fma REVSPH_COMPILER_HAS_MNO_FMA)
if(REVSPH_COMPILER_HAS_MNO_FMA)
  target_compile_options(revsph_flags INTERFACE -mno-fma)
endif()

# Eigen's SIMD paths order sums their own way and use fused multiply-adds on aarch64 (NEON's
# vfmaq_f64, which -ffp-contract=off cannot stop): its scalar path keeps the bits the same on
# every CPU.
target_compile_definitions(revsph_flags INTERFACE EIGEN_DONT_VECTORIZE)
target_include_directories(revsph_flags INTERFACE ${PROJECT_SOURCE_DIR})

option(REVSPH_SANITIZE "Build with AddressSanitizer and UndefinedBehaviorSanitizer" OFF)
if(REVSPH_SANITIZE)
  # -fno-sanitize-recover: a UBSan finding aborts the program, so it fails the test that hit it.
  target_compile_options(revsph_flags INTERFACE -fsanitize=address,undefined
    -fno-sanitize-recover=all -fno-omit-frame-pointer)
  target_link_options(revsph_flags INTERFACE -fsanitize=address,undefined -fno-sanitize-recover=all)
endif()
