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
 * same values). A character device (a terminal, /dev/null) is told apart:
 * writing to it never overwrites what it was read from. */
enum { KIND_NONE = 0, KIND_REGULAR = 1, KIND_DIRECTORY = 2, KIND_OTHER = 3, KIND_CHARACTER = 4 };

/* Symbolic links followed before giving up (Linux's own limit is 40). */
enum { MAX_LINK_HOPS = 40 };

/* Tries at a fresh temporary name before giving up. */
enum { TEMP_TRIES = 100 };

static int kind_of(mode_t mode)
{
    if (S_ISREG(mode)) return KIND_REGULAR;
    if (S_ISDIR(mode)) return KIND_DIRECTORY;
    if (S_ISCHR(mode)) return KIND_CHARACTER;
    return KIND_OTHER;
}

static void fill_info(const struct stat *st, int *kind, int64_t *dev, int64_t *ino, int *mode)
{
    *kind = kind_of(st->st_mode);
    *dev = (int64_t)st->st_dev;
    *ino = (int64_t)st->st_ino;
    *mode = (int)(st->st_mode & 07777);
}

/* A write past a file-size limit (ulimit -f) then fails with EFBIG, and a
 * write to a pipe whose reader has gone (hsri2d | head) with EPIPE, which
 * are reported like any other write error, instead of killing the process
 * (SIGXFSZ: gfortran's runtime would print a backtrace; SIGPIPE: status
 * 141 and the temporary output files left behind). */
int hsri2d_ignore_output_signals(void)
{
    if (signal(SIGXFSZ, SIG_IGN) == SIG_ERR) return errno;
    return signal(SIGPIPE, SIG_IGN) == SIG_ERR ? errno : 0;
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

/* Copy text into out (cap bytes), or ENAMETOOLONG. */
static int copy_path(char *out, size_t cap, const char *text)
{
    size_t n = strlen(text);
    if (n + 1 > cap) return ENAMETOOLONG;
    memcpy(out, text, n + 1);
    return 0;
}

/* The file a write to path creates or replaces, as a canonical absolute
 * path, into out (cap bytes; *len its length): realpath when it exists;
 * otherwise symbolic links that point to nothing yet are followed (each
 * relative target taken from its link's directory) to the name that does
 * not exist, whose directory must: its canonical path and that name. On
 * failure out holds the path reached (the last link's target), for the
 * message, and the errno value is returned (ENOENT: a directory on the way
 * is missing; ELOOP: links without end). */
int hsri2d_target_path(const char *path, char *out, size_t cap, size_t *len)
{
    char cur[PATH_MAX], target[PATH_MAX], dir[PATH_MAX];
    int hops, e;
    *len = 0;
    if (cap == 0) return ENAMETOOLONG;
    out[0] = '\0';
    if (copy_path(cur, sizeof cur, path) != 0) return ENAMETOOLONG;
    for (hops = 0; hops <= MAX_LINK_HOPS; hops++) {
        struct stat st;
        char *real = realpath(cur, NULL);
        const char *slash = strrchr(cur, '/');
        const char *name = slash == NULL ? cur : slash + 1;
        size_t dir_len = slash == NULL ? 0 : (size_t)(slash - cur);
        ssize_t n;
        if (real != NULL) {
            e = copy_path(out, cap, real);
            free(real);
            if (e == 0) *len = strlen(out);
            return e;
        }
        e = errno;
        copy_path(out, cap, cur);
        *len = strlen(out);
        if (e != ENOENT) return e;
        /* the directory part of cur: "." when none, "/" at the root */
        if (slash == NULL) {
            strcpy(dir, ".");
        } else if (dir_len == 0) {
            strcpy(dir, "/");
        } else {
            memcpy(dir, cur, dir_len);
            dir[dir_len] = '\0';
        }
        if (lstat(cur, &st) != 0) {
            if (errno != ENOENT) return errno;
            /* the last name is free: its directory must exist */
            if (*name == '\0') return EISDIR;
            real = realpath(dir, NULL);
            if (real == NULL) return errno;
            if (stat(real, &st) != 0 || !S_ISDIR(st.st_mode)) {
                free(real);
                return ENOTDIR;
            }
            if (strlen(real) + 1 + strlen(name) + 1 > cap) {
                free(real);
                return ENAMETOOLONG;
            }
            strcpy(out, strcmp(real, "/") == 0 ? "" : real);
            strcat(out, "/");
            strcat(out, name);
            free(real);
            *len = strlen(out);
            return 0;
        }
        if (!S_ISLNK(st.st_mode)) return ENOENT;
        n = readlink(cur, target, sizeof target - 1);
        if (n < 0) return errno;
        target[n] = '\0';
        if (target[0] == '/' || slash == NULL) {
            if (copy_path(cur, sizeof cur, target) != 0) return ENAMETOOLONG;
        } else {
            if (strlen(dir) + 1 + strlen(target) + 1 > sizeof cur) return ENAMETOOLONG;
            strcpy(cur, dir);
            strcat(cur, "/");
            strcat(cur, target);
        }
    }
    return ELOOP;
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
 * /dev/null), or a file named under /dev or /proc, for writing, as it is.
 * O_APPEND: a regular file reached that way (/dev/stdout of a shell's
 * ">> log") is added to, not overwritten from its start. */
int hsri2d_open_for_writing(const char *path, int *fd)
{
    *fd = open(path, O_WRONLY | O_APPEND | O_CLOEXEC);
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

/* Make the directory path (its parent must exist); one that exists is not
 * an error. */
int hsri2d_make_dir(const char *path)
{
    struct stat st;
    if (mkdir(path, 0777) == 0) return 0;
    if (errno == EEXIST && stat(path, &st) == 0 && S_ISDIR(st.st_mode)) return 0;
    return errno;
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
