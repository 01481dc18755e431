!> The runs c12-methods compares, for programs only: the definition's scene
!> at a given e, the reference run on a scene, and a method prepared for a
!> scene. A scene or method that is refused stops the program with its
!> message (fail of sphere_row_study_cli): the settings are the program's own.
module sphere_row_method_runs
    use sphere_row, only: qp, scene_t, scene_init, status_normal
    use sphere_row_outcome, only: outcome_t
    use sphere_row_methods, only: method_t, reference_method, method_prepare, method_run
    use sphere_row_study_cli, only: fail
    implicit none
    private
    public :: scene_at, reference_run, prepare_method

contains

    !> The definition's scene with restitution `e`.
    subroutine scene_at(e, scene)
        real(qp), intent(in) :: e
        type(scene_t), intent(out) :: scene
        integer :: code
        character(len=200) :: text
        call scene_init(scene, code, text, e=e)
        if (code /= status_normal) call fail(text)
    end subroutine scene_at

    !> The reference method's run of `scene`, recorded.
    subroutine reference_run(scene, ref)
        type(scene_t), intent(in) :: scene
        type(outcome_t), intent(inout) :: ref
        type(method_t) :: method
        method = reference_method()
        call prepare_method(method, scene)
        call method_run(method, ref, record=.true.)
    end subroutine reference_run

    !> Prepare `method` for `scene`.
    subroutine prepare_method(method, scene)
        type(method_t), intent(inout) :: method
        type(scene_t), intent(in) :: scene
        integer :: code
        character(len=200) :: text
        call method_prepare(method, scene, code, text)
        if (code /= status_normal) call fail(text)
    end subroutine prepare_method

end module sphere_row_method_runs
