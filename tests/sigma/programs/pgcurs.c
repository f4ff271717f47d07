/* A PGPLOT-style cursor read (what PGPLOT 5.2.2's /GOC driver does in GRGO11 for PGCURS,
 * tests/data/sigma/pgplot/cursor_exchange.log): draw a page, send the cursor prompt,
 * read the 9-byte report (key, x, ',', y, CR), send the trailer, print what was read.
 * Usage: pgcurs PTY.  Written for camlab88's tests. */
#include <fcntl.h>
#include <stdio.h>
#include <string.h>
#include <termios.h>
#include <unistd.h>

static int put(int fd, const char *s) {
    size_t n = strlen(s);
    while (n > 0) {
        ssize_t k = write(fd, s, n);
        if (k < 0) return -1;
        s += k;
        n -= (size_t)k;
    }
    return 0;
}

int main(int argc, char **argv) {
    struct termios t;
    char reply[9];
    size_t got = 0;
    int fd;
    if (argc != 2) return 2;
    fd = open(argv[1], O_RDWR | O_NOCTTY);
    if (fd < 0 || tcgetattr(fd, &t) != 0) return 2;
    cfmakeraw(&t);
    if (tcsetattr(fd, TCSANOW, &t) != 0) return 2;
    if (put(fd, "+-*/GJBH\f+-*/BH\r\n+-*/DD000CBGAAAHE999CK1GHBH+-*/GJDAFABH"
                "+-*/GJGI151151GJ817151817560151560151151BH"
                "+-*/GICECA484356CFHF") != 0) return 1;
    while (got < sizeof reply) {  /* GRPTER: exactly 9 bytes */
        ssize_t k = read(fd, reply + got, sizeof reply - got);
        if (k <= 0) return 1;
        got += (size_t)k;
    }
    if (put(fd, "+-*/CECBGJB") != 0) return 1;
    printf("CURSOR key=%c x=%.3s y=%.3s end=%02x\n", reply[0], reply + 1, reply + 5,
           (unsigned char)reply[8]);
    return close(fd) == 0 ? 0 : 1;
}
