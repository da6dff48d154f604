"""scripts/paraview-picture.py on a short run (docs/output.md "A picture with ParaView").

    python3 ParaviewPicture.py --app stresscontact --script scripts/paraview-picture.py
                               --deck DECK --out DIR [--pvpython PATH] [--set KEY=VALUE ...]

Runs the deck with the --set overrides into DIR (emptied first, so no earlier picture can pass),
then the ParaView script with pvpython, and checks the picture: a PNG file of the requested size, whose
pixels are not one flat colour and hold more than 50 colours (the colour map of the body and the
status colours of the contact points; a blank or background-only view has a handful), and the
script's exit status 0. Standard library only (the PNG is decoded here with zlib).
Debian's ParaView renders through GLX: without an X display this starts its own Xvfb, which
picks a free display number itself (-displayfd; two `xvfb-run -a` started at once can race for
the same number), checks that it answers, and stops it afterwards.
Exit status 77 (skipped) when pvpython is not installed (Debian: paraview python3-paraview) or
there is no X display and no Xvfb (Debian: xvfb); 1 on a failed check.
"""

import argparse
import os
import shutil
import socket
import struct
import subprocess
import sys
import time
import zlib

from run_deck import run_deck

WIDTH, HEIGHT = 1000, 450


def png_pixels(path):
    """(width, height, rows of bytes per pixel) of an 8-bit RGB or RGBA PNG, or an error text."""
    with open(path, "rb") as f:
        data = f.read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        return "not a PNG file"
    pos, idat, header = 8, b"", None
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        chunk = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", chunk)
        elif kind == b"IDAT":
            idat += chunk
        pos += 12 + length
    if header is None:
        return "no IHDR chunk"
    width, height, depth, colour, _, _, interlace = header
    if depth != 8 or colour not in (2, 6) or interlace:
        return f"unexpected PNG format (depth {depth}, colour type {colour}, interlace {interlace})"
    bpp = 3 if colour == 2 else 4
    raw = zlib.decompress(idat)
    stride = width * bpp
    rows, prev = [], bytearray(stride)
    for y in range(height):
        ftype = raw[y * (stride + 1)]
        line = bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - bpp] if i >= bpp else 0
            b = prev[i]
            c = prev[i - bpp] if i >= bpp else 0
            if ftype == 1:
                line[i] = (line[i] + a) & 255
            elif ftype == 2:
                line[i] = (line[i] + b) & 255
            elif ftype == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif ftype == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(bytes(line))
        prev = line
    return width, height, bpp, rows


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--app", required=True)
    parser.add_argument("--script", required=True)
    parser.add_argument("--deck", required=True)
    parser.add_argument("--out", required=True)
    parser.add_argument("--pvpython", default="")
    parser.add_argument("--set", action="append", default=[], dest="sets")
    args = parser.parse_args()
    pvpython = args.pvpython if args.pvpython and os.path.exists(args.pvpython) else shutil.which("pvpython")
    if not pvpython:
        print("skipped: pvpython is not installed (Debian: apt-get install paraview python3-paraview)")
        return 77
    env = dict(os.environ)
    xvfb = None
    if not env.get("DISPLAY"):
        if not shutil.which("Xvfb"):
            print("skipped: no X display and no Xvfb for ParaView's rendering (Debian: apt-get install xvfb)")
            return 77
        xvfb, display = start_xvfb()
        if xvfb is None:
            print("FAILED: Xvfb did not start")
            return 1
        env["DISPLAY"] = display
    try:
        return check(args, pvpython, env)
    finally:
        if xvfb is not None:
            xvfb.terminate()
            xvfb.wait()


def x_server_answers(number):
    """True when the X server on display :number completes the X11 connection set-up.

    Tried as libxcb tries it: the abstract socket first, then the socket file."""
    for address in ("\0/tmp/.X11-unix/X" + number, "/tmp/.X11-unix/X" + number):
        try:
            with socket.socket(socket.AF_UNIX, socket.SOCK_STREAM) as s:
                s.settimeout(5)
                s.connect(address)
                # byte order 'l', protocol 11.0, no authorisation
                s.sendall(struct.pack("<cxHHHHxx", b"l", 11, 0, 0, 0))
                reply = s.recv(1)
                return reply == b"\x01"
        except OSError:
            continue
    return False


def start_xvfb():
    """An Xvfb server on a free display that answers: (process, ":N") or (None, None).

    Two Xvfb started at once can both report a display although one of them lost the race for its
    socket (seen with two of these tests in parallel: ParaView then aborts with "bad X server
    connection"), so the display is checked with a connection set-up and a failed server is
    replaced, up to five times."""
    for _ in range(5):
        read_end, write_end = os.pipe()
        server = subprocess.Popen(["Xvfb", "-displayfd", str(write_end), "-screen", "0", "1280x1024x24",
                                   "-nolisten", "tcp"], pass_fds=(write_end,), stderr=subprocess.DEVNULL)
        os.close(write_end)
        number = b""
        while not number.endswith(b"\n"):
            c = os.read(read_end, 1)
            if not c:
                break
            number += c
        os.close(read_end)
        number = number.decode().strip()
        if number.isdigit() and server.poll() is None and x_server_answers(number):
            return server, ":" + number
        server.kill()
        server.wait()
        time.sleep(0.2)
    return None, None


def check(args, pvpython, env):

    if not run_deck(args.app, args.deck, args.out, args.sets):
        return 1
    png = os.path.join(args.out, "picture.png")
    cmd = [pvpython, "--force-offscreen-rendering", args.script, args.out, "--output", png,
           "--size", str(WIDTH), str(HEIGHT)]
    picture = subprocess.run(cmd, capture_output=True, text=True, env=env)
    if picture.returncode != 0 and "bad X server connection" in picture.stdout + picture.stderr:
        # seen only with two ParaView processes starting on fresh Xvfb servers at the same
        # moment (the tests take a CTest resource lock for that): once more, after a second
        print("ParaView could not connect to the X server; trying once more")
        time.sleep(1)
        picture = subprocess.run(cmd, capture_output=True, text=True, env=env)
    # ParaView's start-up chatter and crash traces can be long: the last lines say what happened
    print("\n".join((picture.stdout + picture.stderr).splitlines()[-15:]))
    failures = []
    if picture.returncode != 0:
        failures.append(f"paraview-picture.py exited with {picture.returncode}")
    if not os.path.isfile(png) or os.path.getsize(png) == 0:
        failures.append(f"{png} is missing or empty")
    else:
        decoded = png_pixels(png)
        if isinstance(decoded, str):
            failures.append(f"{png}: {decoded}")
        else:
            width, height, bpp, rows = decoded
            if (width, height) != (WIDTH, HEIGHT):
                failures.append(f"{png} is {width} x {height} pixels, not {WIDTH} x {HEIGHT}")
            colours = set()
            for row in rows:
                colours.update(row[i:i + 3] for i in range(0, len(row), bpp))
            print(f"{png}: {width} x {height} pixels, {len(colours)} colours, {os.path.getsize(png)} bytes")
            if len(colours) <= 1:
                failures.append("the picture is one flat colour")
            elif len(colours) <= 50:
                failures.append(f"the picture has only {len(colours)} colours (a blank view?)")
    for failure in failures:
        print("FAILED:", failure)
    print(f"{os.path.basename(args.deck)}: {'FAILED' if failures else 'ok'}")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
