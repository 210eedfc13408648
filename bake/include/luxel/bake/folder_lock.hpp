#pragma once
// One luxel process at a time in a bake folder.
//
// Renders of one scene started together (a script's loop, ctest -j) share its bake folder: without
// a lock, each finds no bake, bakes, and writes the same files while the other reads them. The
// lock makes the second wait for the first and then load what it kept.

#include <functional>
#include <string>

namespace luxel::bake {

/// An exclusive advisory lock on `directory` (flock(2) on DIRECTORY/.lock; the folder is created
/// if missing) held for the object's lifetime, released by the kernel if the process dies.
/// `waiting` is called once, before blocking, when another holder has it. A folder where the lock
/// file cannot be made (read-only: a bake shipped with a scene) is used unlocked, since nothing
/// of ours can write there either; so is one on a file system that refuses locks. Locks taken through separate objects exclude each other even in
/// one process, so a holder must not take the same folder's lock again. Throws
/// std::runtime_error "DIR: problem" when the folder cannot be created.
class FolderLock {
 public:
  explicit FolderLock(const std::string& directory, const std::function<void()>& waiting = {});
  ~FolderLock();
  FolderLock(const FolderLock&) = delete;
  FolderLock& operator=(const FolderLock&) = delete;

  /// Whether the lock is held (false for a folder used unlocked).
  bool held() const { return fd_ >= 0; }

 private:
  int fd_ = -1;
};

}  // namespace luxel::bake
