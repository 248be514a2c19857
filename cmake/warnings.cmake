# SPDX-License-Identifier: LGPL-3.0-or-later
# Project-wide compile settings: warnings, reproducible doubles, optional strictness and sanitizers.
# exbsp_options is linked by exbsp's own targets (modules, CLI, tests, benchmarks) and never
# installed: the installed libraries carry none of these flags to consumers (docs/package.md).
add_library(exbsp_options INTERFACE)
target_compile_features(exbsp_options INTERFACE cxx_std_17)
target_compile_options(exbsp_options INTERFACE -Wall -Wextra -ffp-contract=off)
if(EXBSP_STRICT)
  target_compile_options(exbsp_options INTERFACE -Werror)
endif()
if(EXBSP_SANITIZE)
  target_compile_options(exbsp_options INTERFACE -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined)
  target_link_options(exbsp_options INTERFACE -fsanitize=address,undefined)
  # GCC 12 reports -Wmaybe-uninitialized false positives inside CGAL's filtered predicates
  # and <regex> once ASan instruments them; they are not in exbsp's code.
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
    target_compile_options(exbsp_options INTERFACE -Wno-maybe-uninitialized)
  endif()
endif()
if(EXBSP_TSAN)
  if(EXBSP_SANITIZE)
    message(FATAL_ERROR "EXBSP_TSAN and EXBSP_SANITIZE cannot be combined")
  endif()
  # GCC's libgomp is not instrumented and synchronises its thread pool with futexes TSan cannot
  # see (false races between parallel regions); clang's libomp with archer tells TSan about
  # OpenMP's barriers and tasks. scripts/test --tsan builds with clang++.
  target_compile_options(exbsp_options INTERFACE -fsanitize=thread -fno-omit-frame-pointer)
  target_link_options(exbsp_options INTERFACE -fsanitize=thread)
endif()
