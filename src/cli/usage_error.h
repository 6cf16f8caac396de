// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef BODT_CLI_USAGE_ERROR_H
#define BODT_CLI_USAGE_ERROR_H

#include <stdexcept>

namespace bodt_cli {

/// Wrong command-line usage found after parsing (e.g. an unusable output path): exit status 2.
struct Usage_error : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

} // namespace bodt_cli

#endif // BODT_CLI_USAGE_ERROR_H
