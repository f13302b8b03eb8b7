#pragma once
#include <filesystem>
#include <string>

namespace gi {

// out/index.html: one row per lesson that has run under `folder` -- each subfolder
// holding an outputs.json -- with its status, its command line and links to its
// report page and its viewer. Made from the records alone, so it shows every lesson
// run so far, in folder order. A record that cannot be read is a row that says so.
std::string lessons_index_page(const std::filesystem::path& folder);

// Writes lessons_index_page(folder) to folder/index.html atomically, holding an
// exclusive lock on the folder from reading the records to the rename: of two
// lessons that finish together, the second to take the lock sees the first's
// record, so neither is lost. Throws WriteError.
void update_lessons_index(const std::filesystem::path& folder);

}  // namespace gi
