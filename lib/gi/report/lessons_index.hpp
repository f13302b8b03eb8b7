#pragma once
#include <filesystem>
#include <string>

namespace gi {

// out/index.html, the course's table of contents: one row per lesson (every lesson
// with a doc, then any other subfolder of `folder` holding an outputs.json), in
// folder order, with its title linked to its report page, the first sentence of what
// it shows, its status -- "not run yet", "running", "complete", the error that
// stopped it, or "killed" for a record still saying "running" whose process is gone
// (run_process.hpp) -- and links to its chapter, its lab and its viewer. Made from
// the records alone; a record that cannot be read is a row that says so.
std::string lessons_index_page(const std::filesystem::path& folder);

// Writes lessons_index_page(folder) to folder/index.html atomically, holding an
// exclusive lock on the folder from reading the records to the rename: of two
// lessons that finish together, the second to take the lock sees the first's
// record, so neither is lost. Throws WriteError.
void update_lessons_index(const std::filesystem::path& folder);

}  // namespace gi
