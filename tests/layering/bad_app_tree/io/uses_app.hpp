#pragma once
// A planted violation for the test layering_rejects_io_using_app: io (the formats) sits below
// app (the life of a run) and may not include it.
#include "app/cli.hpp"
#include "io/table.hpp"
