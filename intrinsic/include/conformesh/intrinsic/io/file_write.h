// file_write.h — writing a whole file so that no reader ever sees half of it: every writer of the library (meshes,
// VTK, VTU, the viewer page, sampled fields, a sweep's records) goes through here.
//
// The bytes go to a temporary name unique to this process and call, in the target's folder (so that rename() stays on
// one file system), are written completely and closed (and fsynced when asked), then renamed over the target. On any
// failure the temporary is removed, the target is left as it was, and InputError names the target and the system's
// reason ("PATH: cannot write: No such file or directory").
#pragma once

#include <string>

namespace conformesh::intrinsic {

// `sync`: fsync before the rename, so that the file survives a crash of the machine once this returns (a sweep's
// records, which a rerun trusts); off for ordinary outputs, where it costs a disk round trip per file.
void writeFileAtomically(const std::string& path, const std::string& bytes, bool sync = false);

}  // namespace conformesh::intrinsic
