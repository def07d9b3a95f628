"""Byte and char fields as course code fills them: std_msgs Byte, Char and UInt8, a
UInt8MultiArray and an Image's data from bytes, a bytearray, a list and a range, a
ByteMultiArray of bytes objects, what each stores (array.array('B'), a list of bytes),
bytes() of it back, equality, repr, and the values each refuses."""
import os

os.environ["ROS_PYTHON_CHECK_FIELDS"] = "1"

import array  # noqa: E402

from sensor_msgs.msg import Image  # noqa: E402
from std_msgs.msg import Byte, ByteMultiArray, Char, UInt8, UInt8MultiArray  # noqa: E402


def attempt(label, make):
    try:
        value = make()
    except Exception as err:
        print(f"{label}: {type(err).__name__}")
        return None
    print(f"{label}: {value!r}")
    return value


def main():
    attempt("Byte()", Byte)
    attempt("Byte(b'\\x07')", lambda: Byte(data=b"\x07"))
    attempt("Byte(7)", lambda: Byte(data=7))
    attempt("Byte(b'ab')", lambda: Byte(data=b"ab"))
    attempt("Char()", Char)
    attempt("Char(65)", lambda: Char(data=65))
    attempt("Char('A')", lambda: Char(data="A"))
    attempt("Char(300)", lambda: Char(data=300))
    attempt("UInt8(255)", lambda: UInt8(data=255))
    attempt("UInt8(256)", lambda: UInt8(data=256))
    for label, data in (("bytes", b"\x01\x02\xff"), ("bytearray", bytearray(b"\x00\x10")), ("list", [1, 2, 3]),
                        ("range", range(4)), ("tuple", (9, 8)), ("array B", array.array("B", [5, 6])),
                        ("array b", array.array("b", [5, 6])), ("negative", [-1]), ("too big", [256]),
                        ("str", "abc"), ("floats", [1.0])):
        msg = attempt(f"UInt8MultiArray {label}", lambda data=data: UInt8MultiArray(data=data))
        if msg is not None:
            print("   type:", type(msg.data).__name__, msg.data.typecode, "bytes:", bytes(msg.data), "len:", len(msg.data))
    a = UInt8MultiArray(data=b"\x01\x02")
    b = UInt8MultiArray(data=[1, 2])
    print("equal bytes/list:", a == b)
    a.data.append(3)
    print("appended:", list(a.data), a == b)
    image = Image(height=1, width=3, encoding="mono8", step=3, data=bytes([10, 20, 30]))
    print("image data:", image.data, bytes(image.data), image.data[1])
    image.data = bytearray(b"\x01\x02\x03")
    print("image bytearray:", image.data)
    for label, data in (("bytes objects", [b"a", b"\x00"]), ("ints", [1, 2]), ("bytes", b"ab")):
        msg = attempt(f"ByteMultiArray {label}", lambda data=data: ByteMultiArray(data=data))
        if msg is not None:
            print("   type:", type(msg.data).__name__, msg.data)


if __name__ == "__main__":
    main()
