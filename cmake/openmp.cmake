# SPDX-License-Identifier: LGPL-3.0-or-later
# OpenMP parallelises candidate evaluation in the min-split heuristic (2 cores here).
find_package(OpenMP REQUIRED COMPONENTS CXX)
