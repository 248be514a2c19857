# SPDX-License-Identifier: LGPL-3.0-or-later
find_package(nlohmann_json 3 REQUIRED)
