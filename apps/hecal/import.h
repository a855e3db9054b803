// `hecal import` (docs/cli.md#hecal-import, docs/import-formats.md): another tool's calibration
// samples → the canonical pose tables, all or nothing. The job is jobs::ImportSamples
// (jobs/import.h; the readers and their conventions are include/hecal/io/import*.h); this
// command binds the flags to its options, checks the output paths and writes the files.
#pragma once

#include "cli.h"
#include "hecal/hecal.h"

namespace hecal::cli {

// Runs the import job (jobs/import.h), checks the output paths and writes the files; throws
// hecal::InputError for bad flags or input.
void RunImport(const jobs::ImportJobOptions& options, const Io& io);

}  // namespace hecal::cli
