"""symcontact.Problem: reading, editing by key path, and errors identical to the command line's."""

import pytest

import symcontact
from conftest import EXAMPLES

INCLINED = EXAMPLES / "inclined_2d" / "inclined_reference.toml"


def test_reads_a_file_and_gets_values_by_either_path_syntax():
    p = symcontact.Problem(INCLINED)
    assert p.dimension == 2 and p.num_steps == 10
    assert p["contact.0.mu"] == 0.2 and p["contact[0].mu"] == 0.2
    assert p["body[1].dirichlet[1].factors"][2] == 0.125
    assert "contact.0.alpha" in p and "contact.0.tau" not in p
    assert p.get("problem.mesh_size") is None


def test_a_change_is_validated_and_a_bad_one_is_undone_with_the_readers_message():
    p = symcontact.Problem(INCLINED)
    p["contact.0.mu"] = 0.3
    assert p["contact.0.mu"] == 0.3
    with pytest.raises(symcontact.InputError) as e:
        p["contact.0.mu"] = -1.0
    assert str(e.value) == f"{INCLINED}: contact[0].mu: expected a number >= 0, got -1"
    assert (e.value.file, e.value.key, e.value.exit_code) == (str(INCLINED), "contact[0].mu", 2)
    assert p["contact.0.mu"] == 0.3  # unchanged
    with pytest.raises(symcontact.InputError, match='contact\\[0\\].muu: unknown key "muu" \\(did you mean "mu"\\?\\)'):
        p["contact.0.muu"] = 0.1
    assert "contact.0.muu" not in p


def test_new_tables_appended_elements_and_removals():
    p = symcontact.Problem(INCLINED)
    p["ipopt.tol"] = 1e-9  # the table [ipopt] does not exist yet
    assert p["ipopt"] == {"tol": 1e-9}
    with pytest.raises(symcontact.InputError, match="expected 11 entries"):
        p["steps.load_factors"] = [1.0] * 11  # 11 steps, the `factors` of the conditions have 10
    # Changes valid only together, in one update; None removes a key.
    p.update({"contact.0.friction": "tresca", "contact.0.tau": 1e-3, "contact.0.mu": None})
    assert p["contact.0.friction"] == "tresca" and "contact.0.mu" not in p
    with pytest.raises(symcontact.InputError):
        p.update({"contact.0.friction": "coulomb", "contact.0.mu": 0.1})  # tau is left: all undone
    assert p["contact.0.friction"] == "tresca" and "contact.0.mu" not in p
    del p["ipopt.tol"]
    assert p["ipopt"] == {}
    with pytest.raises(KeyError):
        p["contact.0.name.x"] = 1.0  # through a string
    with pytest.raises(IndexError):
        p["contact.5.mu"] = 0.1


def test_ipopt_options_are_checked_by_ipopt_as_in_the_file():
    p = symcontact.Problem(INCLINED)
    with pytest.raises(symcontact.InputError) as e:
        p["ipopt.no_such_option"] = 1
    assert e.value.key == "ipopt.no_such_option"


def test_a_string_problem_resolves_meshes_against_its_base_dir():
    text = INCLINED.read_text()
    p = symcontact.Problem.from_string(text, base_dir=INCLINED.parent, name="study.toml")
    assert p.name == "study.toml" and p["contact.0.geometry"] == "reference"
    with pytest.raises(symcontact.InputError, match="^study.toml: body\\[0\\].mesh: "):
        symcontact.Problem.from_string(text, base_dir="/nonexistent", name="study.toml")
    with pytest.raises(symcontact.InputError, match="^study.toml: line 1, column"):
        symcontact.Problem.from_string("[problem\n", name="study.toml")


def test_the_messages_are_the_command_lines(cli, tmp_path):
    # The same bad value through Python and in a file given to `symcontact check`.
    text = INCLINED.read_text().replace('mesh = "inclined.geo"', f'mesh = "{INCLINED.parent / "inclined.geo"}"')
    case = tmp_path / "case.toml"
    case.write_text(text)
    p = symcontact.Problem(case)
    with pytest.raises(symcontact.InputError) as e:
        p["body.0.material.nu"] = 0.5
    assert "\nnu = 0.3\n" in text
    case.write_text(text.replace("\nnu = 0.3\n", "\nnu = 0.5\n", 1))  # body 0's
    out = cli("check", case)
    assert out.returncode == e.value.exit_code == 2
    assert out.stderr.strip() == f"symcontact: input error: {e.value}"
