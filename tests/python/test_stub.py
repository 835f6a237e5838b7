# SPDX-License-Identifier: BSD-3-Clause
"""The type stub names what the module holds, class by class, and every call has a docstring."""
import ast
import enum
import os
import unittest

import edgetrack


def stub_names():
    path = os.path.join(os.path.dirname(edgetrack.__file__), "__init__.pyi")
    with open(path) as f:
        tree = ast.parse(f.read())
    top, classes = set(), {}
    for node in tree.body:
        if isinstance(node, ast.ClassDef):
            top.add(node.name)
            members = set()
            for item in node.body:
                if isinstance(item, ast.FunctionDef):
                    members.add(item.name)
                elif isinstance(item, ast.AnnAssign):
                    members.add(item.target.id)
                elif isinstance(item, ast.Assign):
                    members.update(t.id for t in item.targets)
            classes[node.name] = {m for m in members if not m.startswith("_")}
        elif isinstance(node, ast.FunctionDef):
            top.add(node.name)
        elif isinstance(node, ast.AnnAssign):
            top.add(node.target.id)
    return {n for n in top if not n.startswith("_")}, classes


def module_members(cls):
    if hasattr(cls, "__members__"):  # a pybind11 enum: its values
        return set(cls.__members__)
    return {n for n in dir(cls) if not n.startswith("_")}


class StubMatchesModule(unittest.TestCase):
    def test_top_level_names(self):
        top, _ = stub_names()
        module = {n for n in dir(edgetrack._edgetrack) if not n.startswith("_")}
        self.assertEqual(top, module)
        self.assertEqual(set(edgetrack.__all__), module)

    def test_class_members(self):
        _, classes = stub_names()
        for name, members in classes.items():
            cls = getattr(edgetrack, name)
            if issubclass(cls, Exception):
                continue
            with self.subTest(cls=name):
                self.assertEqual(members, module_members(cls))

    def test_docstrings(self):
        for name in edgetrack.__all__:
            obj = getattr(edgetrack, name)
            if isinstance(obj, str):
                continue
            with self.subTest(name=name):
                self.assertTrue(obj.__doc__ and obj.__doc__.strip(), name)
            if isinstance(obj, type) and not hasattr(obj, "__members__") and not issubclass(obj, Exception):
                for member in module_members(obj):
                    with self.subTest(member=name + "." + member):
                        self.assertTrue(getattr(obj, member).__doc__, member)


if __name__ == "__main__":
    unittest.main()
