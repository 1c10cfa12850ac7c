"""The offline planner's parts, one job each; `agent/planner.py` composes them into `OfflinePlanner`.

entries (the predicates and the program being written), state (what the parts share while writing it), variants
(which asset stands for a mention), counts (how many), stacks (what a stack is made of), placing (PLACE-ON, PLACE-IN,
PLACE-ANYWHERE), layout (where things stand on the support), dining (place settings) and scenes (kinds of scene and
their typical objects).
"""
