"""rclpy.task.Future at its edges: set_result twice, set_exception after a result, cancel a
future already done, result() and exception() of a cancelled one, a done callback that raises
(outside an executor: a UserWarning), done callbacks' order, and a Future awaited by a coroutine driven by hand."""
import warnings

from rclpy.task import Future


def attempt(label, action):
    try:
        print(label, "->", repr(action()))
    except Exception as err:
        print(label, "raised", type(err).__name__ + ":", err)


def main():
    twice = Future()
    twice.set_result(1)
    attempt("set_result again", lambda: twice.set_result(2))
    print("result after second set:", twice.result())
    attempt("set_exception after result", lambda: twice.set_exception(ValueError("late")))
    attempt("result after set_exception", twice.result)
    print("exception:", repr(twice.exception()))
    attempt("cancel a done future", twice.cancel)
    print("cancelled:", twice.cancelled(), "done:", twice.done())

    cancelled = Future()
    cancelled.cancel()
    print("cancelled future: cancelled", cancelled.cancelled(), "done", cancelled.done())
    attempt("result of cancelled", cancelled.result)
    attempt("exception of cancelled", cancelled.exception)
    attempt("set_result on cancelled", lambda: cancelled.set_result(5))
    print("after set_result: cancelled", cancelled.cancelled(), "result", cancelled.result())

    pending = Future()
    print("pending: done", pending.done(), "result", pending.result(), "exception", pending.exception())

    order = []
    ordered = Future()
    ordered.add_done_callback(lambda f: order.append("first"))
    ordered.add_done_callback(lambda f: order.append("second"))
    ordered.set_result("x")
    print("order:", order)

    def bad_callback(f):
        raise RuntimeError("callback failed")

    raising = Future()
    raising.add_done_callback(bad_callback)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        attempt("set_result with a raising callback", lambda: raising.set_result(7))
    print("warned:", [(w.category.__name__, str(w.message)) for w in caught])
    print("done after raising callback:", raising.done(), raising.result())

    awaited = Future()

    async def waiter():
        value = await awaited
        return value * 2

    coroutine = waiter()
    attempt("first send", lambda: coroutine.send(None))
    awaited.set_result(21)
    try:
        coroutine.send(None)
    except StopIteration as stop:
        print("coroutine returned:", stop.value)


if __name__ == "__main__":
    main()
