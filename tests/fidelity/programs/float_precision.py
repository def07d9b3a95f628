"""float32 fields round what they store, float64 fields keep it; numeric arrays are array.array."""
import math

from geometry_msgs.msg import Point, Point32, Polygon
from std_msgs.msg import Float32, Float64, Float64MultiArray, Int16MultiArray


def main():
    print(Point32(x=0.1).x, Point(x=0.1).x, Float32(data=1 / 3).data, Float64(data=1 / 3).data)
    print(Float32(data=math.pi).data == math.pi, Float32(data=3.4e38).data)
    poly = Polygon(points=[Point32(x=0.1, y=0.2), Point32(x=1.5)])
    print([(p.x, p.y) for p in poly.points])
    arr = Float64MultiArray(data=[0.1, 0.2])
    print(type(arr.data).__name__, arr.data.typecode, list(arr.data))
    ints = Int16MultiArray(data=[1, -2])
    print(ints.data.typecode, list(ints.data))
    ints.data.append(3)
    print(list(ints.data))


if __name__ == "__main__":
    main()
