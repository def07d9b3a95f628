"""Default messages of the common packages: repr, fields and their types, constants."""
from geometry_msgs.msg import (
    AccelStamped,
    Inertia,
    PolygonStamped,
    PoseArray,
    PoseWithCovariance,
    Quaternion,
    TransformStamped,
    Twist,
    TwistStamped,
    VelocityStamped,
    WrenchStamped,
)
from nav_msgs.msg import GridCells, MapMetaData, OccupancyGrid, Odometry, Path
from nav_msgs.srv import GetMap, GetPlan
from sensor_msgs.msg import (
    BatteryState,
    CameraInfo,
    Image,
    Imu,
    JointState,
    Joy,
    LaserScan,
    NavSatFix,
    NavSatStatus,
    PointCloud2,
    PointField,
    Range,
    Temperature,
)
from std_msgs.msg import (
    ColorRGBA,
    Float64MultiArray,
    Header,
    MultiArrayDimension,
    String,
    UInt8MultiArray,
)
from std_srvs.srv import SetBool, Trigger

CLASSES = [
    AccelStamped, Inertia, PolygonStamped, PoseArray, Quaternion, TransformStamped, Twist, TwistStamped,
    VelocityStamped, WrenchStamped, GridCells, MapMetaData, OccupancyGrid, Path, BatteryState, Image, Joy,
    JointState, LaserScan, NavSatStatus, PointCloud2, PointField, Range, Temperature, ColorRGBA,
    Float64MultiArray, Header, MultiArrayDimension, String, UInt8MultiArray,
    GetMap.Request, GetPlan.Request, SetBool.Request, SetBool.Response, Trigger.Response,
]


def main():
    for cls in CLASSES:
        print(repr(cls()))
        print("  ", cls.get_fields_and_field_types())
    print(NavSatStatus.STATUS_NO_FIX, NavSatStatus.STATUS_GBAS_FIX, NavSatStatus.SERVICE_GALILEO)
    print(PointField.FLOAT32, PointField.UINT8, Range.ULTRASOUND, Range.INFRARED)
    print(BatteryState.POWER_SUPPLY_STATUS_CHARGING, BatteryState.POWER_SUPPLY_TECHNOLOGY_LIPO)
    # fixed-size numeric arrays are numpy arrays in ROS, lists in turtletui: fields only
    for cls in (PoseWithCovariance, Imu, CameraInfo, Odometry, NavSatFix):
        print(cls.__name__, cls.get_fields_and_field_types())
    print("covariance", [float(v) for v in PoseWithCovariance().covariance][:3], len(PoseWithCovariance().covariance))
    print("k", [float(v) for v in CameraInfo().k])


if __name__ == "__main__":
    main()
