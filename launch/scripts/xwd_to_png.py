#!/usr/bin/env python3
# An Xvfb screen (-fbdir: XWD, ZPixmap, 24/32-bit TrueColor) to PNG with the standard library
# alone, for stack_screenshot.sh. Usage: xwd_to_png.py SCREEN.xwd OUT.png
import struct
import sys
import zlib


def main(src, dst):
    data = open(src, 'rb').read()
    # XWDFileHeader: 25 CARD32, big-endian (X11/XWDFile.h).
    h = struct.unpack('>25I', data[:100])
    header_size, fmt, depth, width, height = h[0], h[2], h[3], h[4], h[5]
    byte_order, bits_per_pixel, bytes_per_line = h[7], h[11], h[12]
    red_mask, green_mask, blue_mask, ncolors = h[14], h[15], h[16], h[19]
    if fmt != 2 or bits_per_pixel not in (24, 32):
        sys.exit('xwd_to_png: only ZPixmap at 24 or 32 bits per pixel (got format %d, %d bpp)'
                 % (fmt, bits_per_pixel))
    pixels = data[header_size + 12 * ncolors:]
    step = bits_per_pixel // 8
    endian = '<' if byte_order == 0 else '>'

    def shift(mask):
        return (mask & -mask).bit_length() - 1

    rs, gs, bs = shift(red_mask), shift(green_mask), shift(blue_mask)
    rows = []
    for y in range(height):
        line = pixels[y * bytes_per_line:y * bytes_per_line + width * step]
        out = bytearray(b'\x00')  # filter: none
        for x in range(0, width * step, step):
            chunk = line[x:x + step] + (b'\x00' if step == 3 else b'')
            (p,) = struct.unpack(endian + 'I', chunk)
            out += bytes(((p & red_mask) >> rs, (p & green_mask) >> gs, (p & blue_mask) >> bs))
        rows.append(bytes(out))

    def chunk(kind, body):
        return (struct.pack('>I', len(body)) + kind + body +
                struct.pack('>I', zlib.crc32(kind + body) & 0xffffffff))

    png = (b'\x89PNG\r\n\x1a\n' +
           chunk(b'IHDR', struct.pack('>IIBBBBB', width, height, 8, 2, 0, 0, 0)) +
           chunk(b'IDAT', zlib.compress(b''.join(rows), 9)) + chunk(b'IEND', b''))
    open(dst, 'wb').write(png)


if __name__ == '__main__':
    if len(sys.argv) != 3:
        sys.exit('usage: xwd_to_png.py SCREEN.xwd OUT.png')
    main(sys.argv[1], sys.argv[2])
