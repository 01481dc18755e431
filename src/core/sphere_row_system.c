/* The few calls of the operating system that Fortran's own I/O cannot make:
 * what kind of file a path names (so that a device or a FIFO is never opened
 * for reading), reads of standard input in blocks of any length, writes whose
 * failure is reported (gfortran's run-time
 * library drops the error of a write that fails, e.g. on a full disk), files
 * created for such writes, and renaming or removing a file. Each returns 0
 * (or what it made) or the errno of the failure. */
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* 1: a regular file, 2: a directory, 3: anything else (a device, a FIFO, a
 * socket); -errno if the path cannot be looked at (it does not exist, ...). */
int sphere_row_path_kind(const char *path)
{
    struct stat st;
    if (stat(path, &st) != 0) return -errno;
    if (S_ISREG(st.st_mode)) return 1;
    if (S_ISDIR(st.st_mode)) return 2;
    return 3;
}

/* All n bytes of text onto file descriptor fd, resuming after a partial
 * write or a signal. */
int sphere_row_write_all(int fd, const char *text, size_t n)
{
    while (n > 0) {
        ssize_t done = write(fd, text, n);
        if (done < 0) {
            if (errno == EINTR) continue;
            return errno;
        }
        text += done;
        n -= (size_t)done;
    }
    return 0;
}

/* Up to n bytes from fd into text: the count read (0 at the end of the
 * input), or -errno. */
long sphere_row_read_some(int fd, char *text, size_t n)
{
    for (;;) {
        ssize_t done = read(fd, text, n);
        if (done >= 0) return (long)done;
        if (errno != EINTR) return -(long)errno;
    }
}

/* A file opened for writing, created or emptied: its file descriptor, or
 * -errno. */
int sphere_row_create(const char *path)
{
    int fd;
    do {
        fd = open(path, O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
    } while (fd < 0 && errno == EINTR);
    return fd >= 0 ? fd : -errno;
}

/* Close a file descriptor: 0, or the errno of the failure (a write that a
 * network file system reports only now). */
int sphere_row_close(int fd)
{
    return close(fd) == 0 ? 0 : errno;
}

int sphere_row_rename(const char *from, const char *to)
{
    return rename(from, to) == 0 ? 0 : errno;
}

int sphere_row_remove(const char *path)
{
    return unlink(path) == 0 ? 0 : errno;
}

/* The system's text for an errno, cut to n - 1 bytes and ended by a zero. */
void sphere_row_error_text(int code, char *text, size_t n)
{
    if (n == 0) return;
    snprintf(text, n, "%s", strerror(code));
}
