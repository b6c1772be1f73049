"""Converts an X window dump (xwd, 24/32-bit ZPixmap, least significant byte
first, as Xvfb writes it) into a PNG with VTK's writer:

    /usr/bin/python3 xwd-to-png.py SCREEN.xwd OUTPUT.png

Used by scripts/paraview-gui-screenshot.sh (no ImageMagick needed).
"""
import struct
import sys

import numpy
from vtkmodules.util.numpy_support import numpy_to_vtk
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkIOImage import vtkPNGWriter

data = open(sys.argv[1], "rb").read()
header = struct.unpack(">25I", data[:100])
header_size, width, height = header[0], header[4], header[5]
byte_order, bits_per_pixel, bytes_per_line, colours = header[7], header[11], header[12], header[19]
if bits_per_pixel != 32 or byte_order != 0:
    sys.exit("xwd-to-png.py: only 32-bit LSB-first dumps are supported (got %d bits, order %d)"
             % (bits_per_pixel, byte_order))
start = header_size + 12 * colours
rows = numpy.frombuffer(data[start:start + bytes_per_line * height], dtype=numpy.uint8)
pixels = rows.reshape(height, bytes_per_line)[:, :4 * width].reshape(height, width, 4)
rgb = numpy.ascontiguousarray(pixels[::-1, :, [2, 1, 0]])  # BGRX, VTK's rows bottom-up
image = vtkImageData()
image.SetDimensions(width, height, 1)
image.GetPointData().SetScalars(numpy_to_vtk(rgb.reshape(-1, 3)))
writer = vtkPNGWriter()
writer.SetInputData(image)
writer.SetFileName(sys.argv[2])
writer.Write()
