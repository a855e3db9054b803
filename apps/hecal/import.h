// `hecal import` (docs/cli.md#hecal-import, docs/import-formats.md): another tool's calibration
// samples → the canonical pose tables, all or nothing. The job is jobs::ImportSamples
// (io/import_job.h; the readers and their conventions are include/hecal/io/import*.h); this
// command binds the flags to its options, checks the output paths and writes the files.
#pragma once

#include "cli.h"
#include "hecal/jobs/import.h"

namespace hecal::cli {

// Runs the import job (io/import_job.h), checks the output paths and writes the files; throws
// hecal::InputError for bad flags or input.
void RunImport(const jobs::ImportJobOptions& options, const Io& io);

}  // namespace hecal::cli
