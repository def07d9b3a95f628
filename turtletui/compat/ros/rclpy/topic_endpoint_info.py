from turtletui.compat.graph_info import TopicEndpointInfo, TopicEndpointTypeEnum  # noqa: F401
