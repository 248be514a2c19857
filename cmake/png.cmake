# SPDX-License-Identifier: LGPL-3.0-or-later
find_package(PNG REQUIRED)
