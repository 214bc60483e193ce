/* POSIX file operations for hsri2d's output files, called from Fortran
 * through the module posix_files (src/common/posix_files.f90).
 *
 * Why C: gfortran's own I/O loses write errors (a full disk or a file-size
 * limit gives iostat = 0 on WRITE, FLUSH and CLOSE alike, gfortran 12), and
 * standard Fortran has no rename, no file identity, no realpath, no fsync.
 *
 * Every function returns 0 on success or an errno value; none prints,
 * allocates memory that outlives the call, or exits. */
#define _XOPEN_SOURCE 700 /* POSIX.1-2008 with XSI: realpath, fchmod */

#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <signal.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <time.h>
#include <unistd.h>

/* What kind of file a path or descriptor is (posix_files.f90 has the
 * same values). */
enum { KIND_NONE = 0, KIND_REGULAR = 1, KIND_DIRECTORY = 2, KIND_OTHER = 3 };

/* Tries at a fresh temporary name before giving up. */
enum { TEMP_TRIES = 100 };

static int kind_of(mode_t mode)
{
    if (S_ISREG(mode)) return KIND_REGULAR;
    if (S_ISDIR(mode)) return KIND_DIRECTORY;
    return KIND_OTHER;
}

static void fill_info(const struct stat *st, int *kind, int64_t *dev, int64_t *ino, int *mode)
{
    *kind = kind_of(st->st_mode);
    *dev = (int64_t)st->st_dev;
    *ino = (int64_t)st->st_ino;
    *mode = (int)(st->st_mode & 07777);
}

/* A write past a file-size limit (ulimit -f) then fails with EFBIG, which
 * is reported like any other write error, instead of killing the process
 * (gfortran's runtime would print a backtrace for the signal). */
int hsri2d_ignore_file_size_signal(void)
{
    return signal(SIGXFSZ, SIG_IGN) == SIG_ERR ? errno : 0;
}

/* Kind, device, inode and permission bits of the file at path (symbolic
 * links followed). A path that does not exist gives ENOENT. */
int hsri2d_file_info(const char *path, int *kind, int64_t *dev, int64_t *ino, int *mode)
{
    struct stat st;
    *kind = KIND_NONE;
    *dev = 0;
    *ino = 0;
    *mode = 0;
    if (stat(path, &st) != 0) return errno;
    fill_info(&st, kind, dev, ino, mode);
    return 0;
}

/* The same for an open descriptor (standard output, for instance). */
int hsri2d_fd_info(int fd, int *kind, int64_t *dev, int64_t *ino, int *mode)
{
    struct stat st;
    *kind = KIND_NONE;
    *dev = 0;
    *ino = 0;
    *mode = 0;
    if (fstat(fd, &st) != 0) return errno;
    fill_info(&st, kind, dev, ino, mode);
    return 0;
}

/* The canonical absolute path of an existing file (realpath) into out,
 * which has room for cap bytes; *len is its length. */
int hsri2d_real_path(const char *path, char *out, size_t cap, size_t *len)
{
    char *real = realpath(path, NULL);
    size_t n;
    *len = 0;
    if (real == NULL) return errno;
    n = strlen(real);
    if (n + 1 > cap) {
        free(real);
        return ENAMETOOLONG;
    }
    memcpy(out, real, n + 1);
    free(real);
    *len = n;
    return 0;
}

/* Whether this process may write the existing file at path. */
int hsri2d_check_writable(const char *path)
{
    return access(path, W_OK) == 0 ? 0 : errno;
}

/* A well-mixed 64-bit value (splitmix64 finalizer). */
static uint64_t mix64(uint64_t x)
{
    x ^= x >> 30;
    x *= UINT64_C(0xbf58476d1ce4e5b9);
    x ^= x >> 27;
    x *= UINT64_C(0x94d049bb133111eb);
    x ^= x >> 31;
    return x;
}

/* Create a new file "PREFIX.XXXXXX.part" (XXXXXX: six letters or digits,
 * different for every process and try), exclusively, for writing; its
 * name goes to out (cap bytes), the open descriptor to *fd. When mode is
 * not negative the file gets these permission bits, otherwise the
 * default ones (0666 less the umask). */
int hsri2d_create_temp(const char *prefix, int mode, char *out, size_t cap, int *fd)
{
    static const char letters[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789";
    const size_t n_letters = sizeof letters - 1;
    size_t prefix_len = strlen(prefix);
    struct timespec now;
    uint64_t seed;
    int attempt;

    *fd = -1;
    if (prefix_len + sizeof ".XXXXXX.part" > cap) return ENAMETOOLONG;
    clock_gettime(CLOCK_REALTIME, &now);
    seed = mix64(((uint64_t)getpid() << 32) ^ (uint64_t)now.tv_sec ^ ((uint64_t)now.tv_nsec << 20));
    for (attempt = 0; attempt < TEMP_TRIES; attempt++) {
        uint64_t r = mix64(seed + (uint64_t)attempt);
        char *p = out + prefix_len;
        int k, f;
        memcpy(out, prefix, prefix_len);
        *p++ = '.';
        for (k = 0; k < 6; k++) {
            *p++ = letters[r % n_letters];
            r /= n_letters;
        }
        memcpy(p, ".part", sizeof ".part");
        f = open(out, O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (f >= 0) {
            if (mode >= 0 && fchmod(f, (mode_t)mode) != 0) {
                int e = errno;
                close(f);
                unlink(out);
                return e;
            }
            *fd = f;
            return 0;
        }
        if (errno != EEXIST) return errno;
    }
    return EEXIST;
}

/* Open an existing file that is not a regular file (a terminal, a pipe,
 * /dev/null) for writing, as it is. */
int hsri2d_open_for_writing(const char *path, int *fd)
{
    *fd = open(path, O_WRONLY | O_CLOEXEC);
    return *fd >= 0 ? 0 : errno;
}

/* Write all n bytes of buf, going on after partial writes and signals. */
int hsri2d_write_all(int fd, const char *buf, size_t n)
{
    while (n > 0) {
        ssize_t done = write(fd, buf, n);
        if (done < 0) {
            if (errno == EINTR) continue;
            return errno;
        }
        if (done == 0) return EIO;
        buf += done;
        n -= (size_t)done;
    }
    return 0;
}

/* Have the system put a file's data on the disk. Pipes, terminals and
 * devices cannot be synchronized: not an error. */
int hsri2d_sync(int fd)
{
    if (fsync(fd) == 0) return 0;
    if (errno == EINVAL || errno == EROFS || errno == ENOTSUP) return 0;
    return errno;
}

int hsri2d_close(int fd)
{
    /* On Linux the descriptor is released even when close fails, so it is
     * not retried; EINTR leaves nothing to report. */
    if (close(fd) == 0 || errno == EINTR) return 0;
    return errno;
}

/* Synchronize the file (or directory) at path: for a file another library
 * wrote and closed, and for a directory after a rename in it. */
int hsri2d_sync_path(const char *path)
{
    int fd = open(path, O_RDONLY | O_CLOEXEC);
    int e;
    if (fd < 0) return errno;
    e = hsri2d_sync(fd);
    close(fd);
    return e;
}

int hsri2d_rename(const char *from, const char *to)
{
    return rename(from, to) == 0 ? 0 : errno;
}

int hsri2d_remove(const char *path)
{
    return unlink(path) == 0 ? 0 : errno;
}

/* The system's description of an errno value, into out (cap bytes). */
void hsri2d_error_text(int errnum, char *out, size_t cap, size_t *len)
{
    const char *text = strerror(errnum);
    size_t n = strlen(text);
    if (cap == 0) {
        *len = 0;
        return;
    }
    if (n > cap - 1) n = cap - 1;
    memcpy(out, text, n);
    out[n] = '\0';
    *len = n;
}

/* errno itself, for libraries (HDF5) that fail without saying why: cleared
 * before a call, read after it. */
void hsri2d_clear_errno(void)
{
    errno = 0;
}

int hsri2d_errno(void)
{
    return errno;
}
