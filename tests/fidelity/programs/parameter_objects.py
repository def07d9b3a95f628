"""The Parameter class as programs build and read it: the type guessed from a value (lists,
tuples, bytes, array.array, mixed lists), a type and a value that disagree, Type.check,
get_parameter_value, to_parameter_msg and from_parameter_msg, rclpy.parameter's
get_parameter_value (a string read as YAML) and parameter_value_to_python."""
import array

from rcl_interfaces.msg import ParameterValue
from rclpy.parameter import Parameter, get_parameter_value, parameter_value_to_python


def attempt(label, action):
    try:
        print(label, action())
    except Exception as err:
        print(label, "->", type(err).__name__, str(err).splitlines()[0])


def main():
    values = (None, True, 3, 2.5, "hi", [b"a", b"b"], [True, False], [1, 2], (1.5, 2.0), ["a", "b"],
              array.array("d", [1.0]), array.array("i", [1]), [], [1, 2.0], [True, 1], {"a": 1}, b"raw")
    for value in values:
        attempt(f"type of {value!r}:", lambda value=value: Parameter.Type.from_parameter_value(value))
    attempt("DOUBLE with 1:", lambda: Parameter("x", Parameter.Type.DOUBLE, 1))
    attempt("INTEGER with True:", lambda: Parameter("x", Parameter.Type.INTEGER, True).value)
    attempt("type as a str:", lambda: Parameter("x", "double", 1.0))
    attempt("type as an int:", lambda: Parameter("x", 3, 1.0))
    attempt("no value:", lambda: (lambda p: (p.type_, p.value))(Parameter("x")))
    attempt("NOT_SET with 1:", lambda: Parameter("x", Parameter.Type.NOT_SET, 1))
    attempt("BYTE_ARRAY with b'ab':", lambda: Parameter("x", Parameter.Type.BYTE_ARRAY, [b"ab"]))
    attempt("STRING_ARRAY as a tuple:", lambda: Parameter("x", Parameter.Type.STRING_ARRAY, ("a",)).value)
    print("checks:", Parameter.Type.DOUBLE.check(1), Parameter.Type.INTEGER.check(True),
          Parameter.Type.DOUBLE_ARRAY.check(array.array("d", [1.0])), Parameter.Type.STRING_ARRAY.check(array.array("u", "a")))
    print("types:", [(t.name, int(t)) for t in Parameter.Type], str(Parameter.Type.DOUBLE), repr(Parameter.Type.DOUBLE))
    speed = Parameter("speed", value=1.5)
    print(speed.name, speed.type_, speed.value)
    print(speed.get_parameter_value())
    msg = speed.to_parameter_msg()
    print(msg)
    back = Parameter.from_parameter_msg(msg)
    print(back.name, back.type_, back.value)
    ids = Parameter("ids", value=[1, 2, 3])
    print(ids.get_parameter_value().integer_array_value, ids.get_parameter_value().type)
    back = Parameter.from_parameter_msg(ids.to_parameter_msg())
    print("ids back:", back.type_, back.value)
    print("names back:", Parameter.from_parameter_msg(Parameter("n", value=["a"]).to_parameter_msg()).value)
    print("raw back:", Parameter.from_parameter_msg(Parameter("b", value=[b"\x01"]).to_parameter_msg()).value)
    for text in ("1", "1.0", "true", "yes", "hello", "[1, 2]", "[1.0, 2]", "['a', 'b']", "[]", "",
                 "017", "0o17", "1e3", "[true, 1]", "'7'", "~", "a: b: c", "[1, [2]]"):
        attempt(f"parse {text!r}:", lambda text=text: (lambda v: (v.type, parameter_value_to_python(v)))(get_parameter_value(text)))
    attempt("to python, type 99:", lambda: parameter_value_to_python(ParameterValue(type=99)))
    print("to python, default:", parameter_value_to_python(ParameterValue()))


if __name__ == "__main__":
    main()
